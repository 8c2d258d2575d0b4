// Regression test: `npm run bench` hung after printing everything, because the `vite preview`
// it started through npm outlived `server.kill()` (npm died, its vite child kept the port and the
// pipe open). `serve()` now runs vite in a process group of its own and `stop()` ends the group.
import assert from 'node:assert/strict';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';
import { freePort, serve } from './preview-server.mjs';

test('serve() stops the whole preview server: the port is closed and no process is left', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'sylva-serve-'));
  writeFileSync(join(dir, 'index.html'), '<!doctype html><title>ok</title>');
  try {
    const { url, stop, pid } = await serve(await freePort(), { outDir: dir });
    assert.equal((await fetch(url)).status, 200);
    await stop();
    await assert.rejects(fetch(url), 'the server still answers after stop()');
    assert.throws(() => process.kill(-pid, 0), /ESRCH/, 'a process of the group is still alive');
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
