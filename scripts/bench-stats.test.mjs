// The benchmark statistics: medians of odd and even counts, nearest-rank percentiles, rounding.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { median, percentile, round } from './bench-stats.mjs';

test('median, percentile and round', () => {
  assert.equal(median([3, 1, 2]), 2);
  assert.equal(median([4, 1, 3, 2]), 2.5);
  assert.equal(median([]), null);
  // The 95th of 40 samples is the 38th smallest: two slow steps do not move it.
  const steps = Array.from({ length: 40 }, (_, i) => i + 1);
  assert.equal(percentile(steps, 95), 38);
  assert.equal(percentile([], 95), null);
  assert.equal(round(16.855), 16.86);
  assert.equal(round(null), null);
});
