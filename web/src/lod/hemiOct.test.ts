import { describe, expect, it } from 'vitest';
import {
  frameBlend,
  frameDirection,
  frameRay,
  hemiOctDecode,
  hemiOctEncode,
  nearestFrame,
  parallaxHit,
  parallaxSteps,
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

/** Orthographic uv of point p in the view from d (hemiOct.ts frame uv). */
function project(d: Vec3, p: Vec3): [number, number] {
  const { right, up } = viewBasis(d);
  return [dot(p, right) / 2 + 0.5, dot(p, up) / 2 + 0.5];
}

/** A ball (centre c, radius rho) as one view's depth map: front depth along d, or -2. */
function ballDepth(d: Vec3, c: Vec3, rho: number) {
  const { right, up } = viewBasis(d);
  return ([u, v]: [number, number]) => {
    const x = (u - 0.5) * 2;
    const y = (v - 0.5) * 2;
    // p = x right + y up + h d; |p - c|² = rho² → h = c·d ± sqrt(rho² − |lateral offset|²)
    const dx = x - dot(c, right);
    const dy = y - dot(c, up);
    const q = rho * rho - dx * dx - dy * dy;
    return q < 0 ? -2 : dot(c, d) + Math.sqrt(q);
  };
}

describe('depth parallax between frames', () => {
  const eye: Vec3 = [-2.1, 0.7, -2.1];
  // The two frames the e2e test's camera sits between (impostor.spec.ts), and one further off.
  const frames: Vec3[] = [
    frameDirection(1, 3, 8),
    frameDirection(0, 4, 8),
    frameDirection(2, 2, 8),
  ];

  it('moves a frame point by s per unit depth: uv0 + s·h is the point the frame saw', () => {
    for (const p of [
      [0, -0.8, 0],
      [0.05, -0.4, -0.02],
      [0.3, 0.2, -0.2],
      [-0.5, 0.5, 0.4],
    ] as Vec3[]) {
      const w: Vec3 = [p[0] - eye[0], p[1] - eye[1], p[2] - eye[2]];
      for (const d of frames) {
        const { uv0, s } = frameRay(d, eye, w);
        const h = dot(p, d);
        const expected = project(d, p);
        expect(uv0[0] + s[0] * h).toBeCloseTo(expected[0], 9);
        expect(uv0[1] + s[1] * h).toBeCloseTo(expected[1], 9);
      }
    }
  });

  it('takes one march step per 2 texels of travel, at least 2 and at most 32', () => {
    expect(parallaxSteps([0, 0], 160)).toBe(2);
    expect(parallaxSteps([0.03, 0.04], 160)).toBe(8);
    expect(parallaxSteps([1, 0], 160)).toBe(32);
  });

  it('finds the same point of an off-centre trunk-wide ball in every frame (no doubling)', () => {
    const c: Vec3 = [0.04, -0.6, -0.03];
    const rho = 0.05;
    const texel = 1 / 160;
    // Rays at the ball's visible points (toward the eye) and beside it.
    const toEye = unit([eye[0] - c[0], eye[1] - c[1], eye[2] - c[2]]);
    let hits = 0;
    for (let a = -1.5; a <= 1.5; a += 0.25) {
      for (const b of [-0.5, 0, 0.5]) {
        const { right, up } = viewBasis(toEye);
        const off = (k: number) => right[k]! * a * rho + up[k]! * b * rho;
        const target: Vec3 = [c[0] + off(0), c[1] + off(1), c[2] + off(2)];
        const w: Vec3 = [target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]];
        const found = frames.map((d) => {
          const { uv0, s } = frameRay(d, eye, w);
          return parallaxHit(ballDepth(d, c, rho), uv0, s, 160);
        });
        if (Math.hypot(a, b) > 1.2) {
          // Beside the ball: every frame misses (no second, displaced ball).
          for (const f of found) expect(f).toBeNull();
          continue;
        }
        // The rim (grazing rays) is left out: a march step may pass it.
        if (Math.hypot(a, b) > 0.8) continue;
        // The true hit: the ray's entry into the ball.
        const wl = Math.hypot(...w);
        const wn: Vec3 = [w[0] / wl, w[1] / wl, w[2] / wl];
        const oc: Vec3 = [eye[0] - c[0], eye[1] - c[1], eye[2] - c[2]];
        const bq = dot(oc, wn);
        const t = -bq - Math.sqrt(Math.max(bq * bq - dot(oc, oc) + rho * rho, 0));
        const p: Vec3 = [eye[0] + wn[0] * t, eye[1] + wn[1] * t, eye[2] + wn[2] * t];
        for (const [k, d] of frames.entries()) {
          if (dot(unit([p[0] - c[0], p[1] - c[1], p[2] - c[2]]), d) < 0.2) continue; // unseen
          const f = found[k];
          expect(f, `frame ${k} finds the ball`).not.toBeNull();
          const expected = project(d, p);
          expect(Math.abs(f![0] - expected[0])).toBeLessThan(texel);
          expect(Math.abs(f![1] - expected[1])).toBeLessThan(texel);
          hits++;
        }
      }
    }
    expect(hits).toBeGreaterThan(20);
  });
});
