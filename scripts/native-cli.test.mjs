// `node --test scripts/`: the scripts find the CLI where Cargo builds it (regression: they used to
// assume target/ even with CARGO_TARGET_DIR set, and ran a stale or missing binary).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { cliPath } from './native-cli.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));

test('without CARGO_TARGET_DIR the CLI is under target/', () => {
  assert.equal(cliPath({}), join(root, 'target', 'release', 'sylva'));
});

test('an absolute CARGO_TARGET_DIR is used as it is', () => {
  assert.equal(cliPath({ CARGO_TARGET_DIR: '/tmp/elsewhere' }), '/tmp/elsewhere/release/sylva');
});

test('a relative CARGO_TARGET_DIR is taken from the repository root', () => {
  assert.equal(
    cliPath({ CARGO_TARGET_DIR: 'build/t' }),
    join(root, 'build', 't', 'release', 'sylva'),
  );
});
