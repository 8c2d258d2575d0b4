import { describe, expect, it } from 'vitest';
import { switchDistances } from '../lod/selection';
import {
  assignLods,
  buildForestInstancing,
  createBuckets,
  FOREST_LEVELS,
  scatter,
  type ForestLayout,
} from './layout';

function minDistance(layout: ForestLayout): number {
  // Grid hash over cells of the spacing: only neighbouring cells can hold the closest pair.
  const cell = layout.minSpacing * 2;
  const grid = new Map<string, number[]>();
  for (let i = 0; i < layout.count; i++) {
    const key = `${Math.floor(layout.x[i]! / cell)},${Math.floor(layout.z[i]! / cell)}`;
    const list = grid.get(key) ?? [];
    list.push(i);
    grid.set(key, list);
  }
  let best = Infinity;
  for (let i = 0; i < layout.count; i++) {
    const gx = Math.floor(layout.x[i]! / cell);
    const gz = Math.floor(layout.z[i]! / cell);
    for (let a = -1; a <= 1; a++) {
      for (let b = -1; b <= 1; b++) {
        for (const j of grid.get(`${gx + a},${gz + b}`) ?? []) {
          if (j <= i) continue;
          best = Math.min(
            best,
            Math.hypot(layout.x[i]! - layout.x[j]!, layout.z[i]! - layout.z[j]!),
          );
        }
      }
    }
  }
  return best;
}

describe('forest layout', () => {
  it('places exactly n trees, deterministically, apart and within bounds', () => {
    for (const n of [1, 7, 1000, 10_000]) {
      const a = scatter(n, { seed: 42, varieties: 8, spacing: 9 });
      const b = scatter(n, { seed: 42, varieties: 8, spacing: 9 });
      expect(a.count).toBe(n);
      expect(a.x.length).toBe(n);
      expect(Array.from(a.matrices)).toEqual(Array.from(b.matrices));
      expect(Array.from(a.variety)).toEqual(Array.from(b.variety));
      for (let i = 0; i < n; i++) {
        expect(Math.abs(a.x[i]!)).toBeLessThanOrEqual(a.halfSize);
        expect(Math.abs(a.z[i]!)).toBeLessThanOrEqual(a.halfSize);
        expect(a.scale[i]!).toBeGreaterThanOrEqual(0.8);
        expect(a.scale[i]!).toBeLessThanOrEqual(1.2);
        expect(a.variety[i]!).toBeLessThan(8);
      }
      if (n > 1) expect(minDistance(a)).toBeGreaterThanOrEqual(a.minSpacing * (1 - 1e-5));
      expect(a.perVariety.reduce((x, y) => x + y, 0)).toBe(n);
    }
    expect(scatter(1000, { seed: 1, varieties: 8, spacing: 9 }).minSpacing).toBeCloseTo(3.6, 6);
  });

  it('differs with the seed and uses every variety', () => {
    const a = scatter(1000, { seed: 1, varieties: 8, spacing: 9 });
    const b = scatter(1000, { seed: 2, varieties: 8, spacing: 9 });
    expect(Array.from(a.x)).not.toEqual(Array.from(b.x));
    for (const count of a.perVariety) expect(count).toBeGreaterThan(60);
  });

  it('matrices are rotation about Y times scale, at the tree position', () => {
    const a = scatter(50, { seed: 3, varieties: 2, spacing: 5 });
    for (let i = 0; i < 50; i++) {
      const m = a.matrices.subarray(i * 16, i * 16 + 16);
      const s = a.scale[i]!;
      expect(Math.hypot(m[0]!, m[1]!, m[2]!)).toBeCloseTo(s, 5);
      expect(m[5]).toBeCloseTo(s, 5);
      expect(m[12]).toBe(a.x[i]);
      expect(m[13]).toBe(0);
      expect(m[14]).toBe(a.z[i]);
      expect(m[0]! * m[8]! + m[2]! * m[10]!).toBeCloseTo(0, 5);
    }
  });
});

describe('per-LOD bucketing', () => {
  const setup = () => {
    const layout = scatter(2000, { seed: 9, varieties: 4, spacing: 9 });
    const buckets = createBuckets(layout, 4);
    const { out, back } = switchDistances([0.6, 0.3, 0.12], 40);
    const frame = {
      camera: [0, 10, 0] as [number, number, number],
      radius: new Float32Array([5, 6, 7, 8]),
      centreY: new Float32Array([5, 6, 7, 8]),
      out,
      back,
    };
    return { layout, buckets, frame };
  };

  it('puts every tree in exactly one bucket of its variety, nearer trees finer', () => {
    const { layout, buckets, frame } = setup();
    // Iterate to a fixed point (hysteresis starts everyone at the coarsest level).
    assignLods(layout, buckets, frame);
    const visible = assignLods(layout, buckets, frame);
    expect(visible).toBe(layout.count);
    expect(buckets.counts.reduce((a, b) => a + b, 0)).toBe(layout.count);
    expect(buckets.perLevel.reduce((a, b) => a + b, 0)).toBe(layout.count);
    for (let v = 0; v < 4; v++) {
      let sum = 0;
      for (let l = 0; l < FOREST_LEVELS; l++) {
        const c = buckets.counts[v * FOREST_LEVELS + l]!;
        expect(c * 16).toBeLessThanOrEqual(buckets.matrices[v * FOREST_LEVELS + l]!.length);
        sum += c;
      }
      expect(sum).toBe(layout.perVariety[v]);
    }
    // Every level is used by a forest seen from its middle.
    for (let l = 0; l < FOREST_LEVELS; l++) expect(buckets.perLevel[l]!).toBeGreaterThan(0);
    // Level grows with distance (in radii): the largest LOD0 distance < smallest impostor one.
    let maxNear = 0;
    let minFar = Infinity;
    for (let i = 0; i < layout.count; i++) {
      const v = layout.variety[i]!;
      const r = frame.radius[v]! * layout.scale[i]!;
      const d = Math.hypot(layout.x[i]!, frame.centreY[v]! * layout.scale[i]! - 10, layout.z[i]!);
      if (buckets.level[i] === 0) maxNear = Math.max(maxNear, d / r);
      if (buckets.level[i] === 3) minFar = Math.min(minFar, d / r);
    }
    expect(maxNear).toBeLessThan(minFar);
    // The bucket holds the tree's matrix verbatim.
    const b = buckets.matrices[0]!;
    const first = Array.from(b.subarray(0, 16));
    let found = false;
    for (let i = 0; i < layout.count && !found; i++) {
      found = Array.from(layout.matrices.subarray(i * 16, i * 16 + 16)).every(
        (x, k) => x === first[k],
      );
    }
    expect(found).toBe(true);
  });

  it('keeps levels under small camera moves (hysteresis) and culls outside the frustum', () => {
    const { layout, buckets, frame } = setup();
    assignLods(layout, buckets, frame);
    assignLods(layout, buckets, frame);
    // Wobbling the camera back and forth by 2 cm: a tree may cross a band edge once, but never
    // switches back (no popping).
    let previous = Uint8Array.from(buckets.level);
    const switches = new Uint8Array(layout.count);
    for (let k = 0; k < 20; k++) {
      const wobble = k % 2 === 0 ? 0.02 : -0.02;
      assignLods(layout, buckets, { ...frame, camera: [wobble, 10, wobble] });
      for (let i = 0; i < layout.count; i++) if (buckets.level[i] !== previous[i]) switches[i]!++;
      previous = Uint8Array.from(buckets.level);
    }
    expect(Math.max(...switches)).toBeLessThanOrEqual(1);
    expect(switches.reduce((a, b) => a + b, 0)).toBeLessThan(layout.count * 0.01);
    // A frustum of one half-space x ≥ 0 keeps about half the trees.
    const planes = new Float32Array(24);
    for (let p = 0; p < 6; p++) planes[p * 4 + 3] = 1e9;
    planes[0] = 1;
    planes[3] = 0;
    const visible = assignLods(layout, buckets, { ...frame, planes });
    expect(visible).toBeGreaterThan(layout.count * 0.4);
    expect(visible).toBeLessThan(layout.count * 0.6);
  });

  it('builds the instancing data of 10,000 trees within the 200 ms budget', () => {
    buildForestInstancing(10_000, 8); // warm-up
    const times: number[] = [];
    for (let k = 0; k < 5; k++) {
      const t0 = performance.now();
      const { visible } = buildForestInstancing(10_000, 8, k + 1);
      times.push(performance.now() - t0);
      expect(visible).toBe(10_000);
    }
    times.sort((a, b) => a - b);
    expect(times[2]!).toBeLessThan(200);
  });
});
