// `node --test scripts/`: the browser tests use the Chromium setup.sh checked (regression: the
// Playwright config read CHROMIUM_PATH while setup.sh and the README name SYLVA_CHROMIUM).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { chromiumPath } from './chromium.mjs';

test('Debian’s Chromium by default', () => {
  assert.equal(chromiumPath({}), '/usr/bin/chromium');
});

test('SYLVA_CHROMIUM, as setup.sh checks it, wins', () => {
  assert.equal(chromiumPath({ SYLVA_CHROMIUM: '/opt/chrome/chrome' }), '/opt/chrome/chrome');
});
