// `vite preview` of web/dist on a port, for the Node scripts that drive the built app in
// Chromium (the browser benchmark, the gallery). Resolves once the page answers.
import { spawn } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));

/** Starts the server; returns it (kill it when done) and its URL. */
export async function serve(port) {
  const server = spawn(
    'npm',
    ['run', 'preview', '-w', 'web', '--', '--port', String(port), '--strictPort'],
    { cwd: root, stdio: ['ignore', 'pipe', 'pipe'], detached: true },
  );
  const url = `http://127.0.0.1:${port}/`;
  for (let i = 0; i < 100; i++) {
    try {
      if ((await fetch(url)).ok) return { server, url };
    } catch {
      // not up yet
    }
    await new Promise((r) => setTimeout(r, 100));
  }
  stop(server);
  throw new Error('vite preview did not start');
}

/** Stops a server from `serve` (npm and the vite process under it). */
export function stop(server) {
  try {
    process.kill(-server.pid);
  } catch {
    server.kill();
  }
}
