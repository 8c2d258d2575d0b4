/**
 * Benchmark of the forest instancing data (issue #7 item 8: ≤ 200 ms for 10,000 trees).
 * Run: `cd web && npx vitest bench --run src/forest/layout.bench.ts`.
 */
import { bench, describe } from 'vitest';
import { switchDistances } from '../lod/selection';
import { assignLods, buildForestInstancing, createBuckets, scatter } from './layout';

describe('forest instancing, 10,000 trees, 8 varieties', () => {
  bench('scatter + buckets + LOD assignment (cold)', () => {
    buildForestInstancing(10_000, 8);
  });

  const layout = scatter(10_000, { seed: 1, varieties: 8, spacing: 9 });
  const buckets = createBuckets(layout, 8);
  const { out, back } = switchDistances([0.6, 0.3, 0.12], 40);
  const radius = new Float32Array(8).fill(6);
  let k = 0;
  bench('per-frame LOD assignment (warm)', () => {
    k++;
    assignLods(layout, buckets, {
      camera: [Math.sin(k) * 50, 20, Math.cos(k) * 50],
      radius,
      centreY: radius,
      out,
      back,
    });
  });
});
