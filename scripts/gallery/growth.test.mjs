// The growth section's rows: seven ages each, in order, the Mature Age among them, the years
// past it for the life over decades.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { rowAges } from './growth.mjs';

test('every row shows seven ascending ages with its Mature Age', () => {
  for (const [name, mature] of [
    ['default', 40],
    ['oak', 100],
    ['grown_broadleaf', 35],
    ['grown_shrub', 12],
    ['grown_bushy', 20],
  ]) {
    const ages = rowAges(name, mature);
    assert.equal(ages.length, 7, name);
    assert.deepEqual(
      [...ages].sort((a, b) => a - b),
      ages,
      name,
    );
    assert.ok(ages.includes(mature), name);
    assert.ok(ages.at(-1) > mature, `${name}: a year past maturity`);
  }
  assert.deepEqual(rowAges('grown_bushy', 20), [2, 5, 10, 20, 40, 60, 80]);
  assert.deepEqual(rowAges('default', 40), [2, 5, 10, 20, 40, 60, 100]);
});
