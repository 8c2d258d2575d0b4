import { describe, expect, it } from 'vitest';
import {
  frameBlend,
  frameDirection,
  hemiOctDecode,
  hemiOctEncode,
  nearestFrame,
  viewBasis,
  type Vec3,
} from './hemiOct';

const unit = (v: Vec3): Vec3 => {
  const l = Math.hypot(...v);
  return [v[0] / l, v[1] / l, v[2] / l];
};
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** Deterministic directions over the upper hemisphere (Fibonacci spiral). */
function hemisphere(n: number): Vec3[] {
  const out: Vec3[] = [];
  for (let i = 0; i < n; i++) {
    const y = (i + 0.5) / n;
    const r = Math.sqrt(1 - y * y);
    const a = i * 2.399963229728653;
    out.push([r * Math.cos(a), y, r * Math.sin(a)]);
  }
  return out;
}

describe('hemi-octahedral mapping', () => {
  it('round-trips directions of the upper hemisphere', () => {
    for (const d of hemisphere(500)) {
      const [u, v] = hemiOctEncode(d);
      expect(u).toBeGreaterThanOrEqual(0);
      expect(u).toBeLessThanOrEqual(1);
      expect(v).toBeGreaterThanOrEqual(0);
      expect(v).toBeLessThanOrEqual(1);
      const back = hemiOctDecode(u, v);
      expect(dot(back, d)).toBeGreaterThan(1 - 1e-9);
    }
  });

  it('round-trips points of the square', () => {
    for (let i = 0; i <= 20; i++) {
      for (let j = 0; j <= 20; j++) {
        const [u, v] = [i / 20, j / 20];
        const d = hemiOctDecode(u, v);
        expect(Math.hypot(...d)).toBeCloseTo(1, 12);
        expect(d[1]).toBeGreaterThanOrEqual(0);
        const [u2, v2] = hemiOctEncode(d);
        expect(u2).toBeCloseTo(u, 9);
        expect(v2).toBeCloseTo(v, 9);
      }
    }
  });

  it('puts the zenith at the centre and the axes at the corners', () => {
    expect(hemiOctEncode([0, 1, 0])).toEqual([0.5, 0.5]);
    expect(hemiOctEncode([1, 0, 0])).toEqual([1, 1]);
    expect(hemiOctEncode([0, 0, 1])).toEqual([1, 0]);
    expect(hemiOctEncode([-1, 0, 0])).toEqual([0, 0]);
    expect(hemiOctEncode([0, 0, -1])).toEqual([0, 1]);
    // Below the horizon folds onto it.
    const [u, v] = hemiOctEncode(unit([1, -0.5, 0]));
    expect([u, v]).toEqual([1, 1]);
  });

  it('frame (i, j) of an n×n atlas encodes back to its grid vertex', () => {
    for (const n of [8, 12]) {
      for (let i = 0; i < n; i++) {
        for (let j = 0; j < n; j++) {
          const d = frameDirection(i, j, n);
          const [u, v] = hemiOctEncode(d);
          expect(u * (n - 1)).toBeCloseTo(i, 9);
          expect(v * (n - 1)).toBeCloseTo(j, 9);
          expect(nearestFrame(d, n)).toEqual([i, j]);
        }
      }
    }
  });

  it('blends 3 neighbouring frames with weights summing to 1', () => {
    const n = 8;
    for (const d of hemisphere(300)) {
      const { frames, weights } = frameBlend(d, n);
      expect(weights.reduce((a, b) => a + b, 0)).toBeCloseTo(1, 12);
      for (const w of weights) expect(w).toBeGreaterThanOrEqual(-1e-12);
      for (const [i, j] of frames) {
        expect(i).toBeGreaterThanOrEqual(0);
        expect(j).toBeGreaterThanOrEqual(0);
        expect(i).toBeLessThan(n);
        expect(j).toBeLessThan(n);
      }
      // The weighted grid position reproduces the direction's grid position.
      const [u, v] = hemiOctEncode(d);
      const gx = frames.reduce((a, f, k) => a + f[0] * weights[k]!, 0);
      const gy = frames.reduce((a, f, k) => a + f[1] * weights[k]!, 0);
      expect(gx).toBeCloseTo(u * (n - 1), 9);
      expect(gy).toBeCloseTo(v * (n - 1), 9);
      // The nearest frame is close in angle (a cell spans at most ~33° for n = 8).
      const [fi, fj] = nearestFrame(d, n);
      expect(dot(frameDirection(fi, fj, n), d)).toBeGreaterThan(Math.cos((33 * Math.PI) / 180));
    }
  });

  it('view basis is orthonormal and right-handed with the view direction', () => {
    for (const d of [...hemisphere(100), [0, 1, 0] as Vec3]) {
      const { right, up } = viewBasis(d);
      expect(Math.hypot(...right)).toBeCloseTo(1, 9);
      expect(Math.hypot(...up)).toBeCloseTo(1, 9);
      expect(dot(right, up)).toBeCloseTo(0, 9);
      expect(dot(right, d)).toBeCloseTo(0, 9);
      expect(dot(up, d)).toBeCloseTo(0, 9);
      // right × up = d (camera x, y, z)
      const c: Vec3 = [
        right[1] * up[2] - right[2] * up[1],
        right[2] * up[0] - right[0] * up[2],
        right[0] * up[1] - right[1] * up[0],
      ];
      expect(dot(c, d)).toBeCloseTo(1, 9);
      if (d[1] < 0.99) expect(up[1]).toBeGreaterThan(0);
    }
  });
});
