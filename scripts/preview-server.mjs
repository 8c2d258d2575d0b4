// `vite preview` of web/dist (or another folder) for the Node scripts that drive the built app
// in Chromium (the browser benchmark, the gallery, their tests). The server runs in a process
// group of its own and `stop()` ends the whole group: started through npm, vite once outlived
// the npm process it was killed through and kept `npm run bench` from exiting.
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));

/** A TCP port nothing listens on now (a server of another checkout must not answer for ours). */
export function freePort() {
  return new Promise((resolve, reject) => {
    const probe = createServer();
    probe.once('error', reject);
    probe.listen(0, '127.0.0.1', () => {
      const { port } = probe.address();
      probe.close(() => resolve(port));
    });
  });
}

/**
 * Starts `vite preview` of `outDir` (default web/dist) on `port` in a process group of its own,
 * waits until it answers, and returns `{ url, stop }`; `stop()` ends the whole group (vite
 * itself, not only a wrapper) and resolves when it has exited.
 */
export async function serve(port, { outDir } = {}) {
  const vite = fileURLToPath(new URL('../node_modules/vite/bin/vite.js', import.meta.url));
  const args = [vite, 'preview', '--port', String(port), '--strictPort', '--host', '127.0.0.1'];
  if (outDir) args.push('--outDir', outDir);
  const server = spawn(process.execPath, args, {
    cwd: `${root}/web`,
    stdio: 'ignore',
    detached: true,
  });
  const exited = new Promise((resolve) => server.once('exit', resolve));
  const killGroup = () => {
    try {
      process.kill(-server.pid, 'SIGTERM');
    } catch {
      // already gone
    }
  };
  // A bench stopped with Ctrl+C (or ending by an error) takes its server with it.
  const onSignal = () => {
    killGroup();
    process.exit(130);
  };
  process.once('exit', killGroup);
  process.once('SIGINT', onSignal);
  process.once('SIGTERM', onSignal);
  const stop = async () => {
    killGroup();
    await exited;
    process.off('exit', killGroup);
    process.off('SIGINT', onSignal);
    process.off('SIGTERM', onSignal);
  };
  const url = `http://127.0.0.1:${port}/`;
  for (let i = 0; i < 150; i++) {
    try {
      if ((await fetch(url)).ok) return { url, stop, pid: server.pid };
    } catch {
      // not up yet
    }
    if (server.exitCode !== null) break;
    await new Promise((r) => setTimeout(r, 100));
  }
  await stop();
  throw new Error('vite preview did not start');
}
