// The native `sylva` CLI the Node scripts run: built (release) on first use, found where Cargo
// puts it (`$CARGO_TARGET_DIR`, else `target/` at the repository root).
import { execFileSync } from 'node:child_process';
import { isAbsolute, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));

/** Where Cargo puts the release CLI given the environment `env` (a relative `CARGO_TARGET_DIR` is
 * taken from the repository root, where the scripts run cargo). */
export function cliPath(env = process.env) {
  const dir = env.CARGO_TARGET_DIR;
  const target = dir ? (isAbsolute(dir) ? dir : join(root, dir)) : join(root, 'target');
  return join(target, 'release', 'sylva');
}

/** Builds the release CLI (quietly; a no-op when up to date) and returns its path. */
export function nativeCli() {
  execFileSync('cargo', ['build', '--quiet', '--release', '-p', 'sylva-cli'], {
    cwd: root,
    stdio: 'inherit',
  });
  return cliPath();
}
