// The seasons strip shows every broadleaf preset (no conifer), and the close-ups frame a part on
// the crown's outside at mid height.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { broadleaves, outermost, partCamera } from './seasons.mjs';

test('every preset but the evergreen conifers is in the seasons strip', () => {
  const presets = [
    { name: 'default', values: {} },
    { name: 'fir', values: { leaf_phenology: 7 } },
    { name: 'oak', values: { leaf_phenology: 2 } },
    { name: 'cherry', values: { leaf_phenology: 8 } },
  ];
  assert.deepEqual(
    broadleaves(presets).map(({ p, kind }) => [p.name, kind]),
    [
      ['default', 0],
      ['oak', 2],
      ['cherry', 8],
    ],
  );
});

test('the close-up part is the outermost one between a third and three quarters of the top', () => {
  const origins = [
    [0, 10, 0],
    [5, 9, 0],
    [3, 5, 0],
    [0, 4, -4.5],
    [6, 1, 0],
  ];
  assert.deepEqual(outermost(origins), [0, 4, -4.5]);
});

test('a hanging part is seen from under and outside it, an upright one from above', () => {
  const near = (a, b) => a.every((x, i) => Math.abs(x - b[i]) < 1e-9);
  assert.ok(near(partCamera([3, 5, 4], 1, 'below'), [3.36, 4.2, 4.48]));
  assert.ok(near(partCamera([3, 5, 4], 1, 'above'), [3.36, 5.8, 4.48]));
  assert.ok(near(partCamera([0, 2, -2], 0.5, 'out'), [0, 2.125, -2.5]));
});
