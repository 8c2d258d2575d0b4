import { describe, expect, it } from 'vitest';
import {
  displaceAnchor,
  displaceBark,
  effectiveStrength,
  gustEnvelope,
  hash3,
  leafFlutter,
  mainBend,
  smoothCurve,
  smoothTriangleWave,
  triangleWave,
  wave2,
  type Vec3,
  type WindFrame,
  type WindVertex,
} from './wind.math';

const frame = (over: Partial<WindFrame> = {}): WindFrame => ({
  time: 1.7,
  direction: [Math.cos(0.5), Math.sin(0.5)],
  strength: 1,
  gust: [0.5, 0.15],
  enabled: true,
  height: 17,
  radius: 4,
  ...over,
});

const twig: WindVertex = {
  pivot: [2, 9, 1],
  level: 3,
  phase: 0.42,
  stiffness: 0.05,
  distance: 12,
  radius: 0.01,
};

const dist = (a: Vec3, b: Vec3): number => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const len = (a: Vec3): number => Math.hypot(a[0], a[1], a[2]);

/** Deterministic pseudo-random points in and around a 17 m crown. */
function points(n: number): Vec3[] {
  const out: Vec3[] = [];
  let s = 12345;
  const rnd = () => {
    s = (s * 1103515245 + 12345) % 2147483648;
    return s / 2147483648;
  };
  for (let i = 0; i < n; i++) out.push([rnd() * 8 - 4, rnd() * 18 - 0.5, rnd() * 8 - 4]);
  return out;
}

describe('wave functions (GPU Gems 3, ch. 16)', () => {
  it('smooth triangle wave: range 0..1, period 1, SmoothCurve of TriangleWave', () => {
    for (let x = -3; x <= 3; x += 0.0137) {
      const v = smoothTriangleWave(x);
      expect(v).toBeGreaterThanOrEqual(0);
      expect(v).toBeLessThanOrEqual(1);
      expect(smoothTriangleWave(x + 1)).toBeCloseTo(v, 9);
      expect(v).toBeCloseTo(smoothCurve(triangleWave(x)), 12);
    }
    expect(triangleWave(0)).toBeCloseTo(0, 12);
    expect(triangleWave(0.5)).toBeCloseTo(1, 12);
    expect(triangleWave(0.25)).toBeCloseTo(0.5, 12);
    expect(smoothCurve(0)).toBe(0);
    expect(smoothCurve(1)).toBe(1);
    expect(smoothCurve(0.5)).toBe(0.5);
  });

  it('wave2 is centred (−1..1) and the gust envelope stays in 0..1', () => {
    for (let t = 0; t < 40; t += 0.05) {
      const w = wave2(t * 0.375, t * 0.193);
      expect(Math.abs(w)).toBeLessThanOrEqual(1);
      const g = gustEnvelope(t, 0.15);
      expect(g).toBeGreaterThanOrEqual(0);
      expect(g).toBeLessThanOrEqual(1);
    }
  });

  it('hash3 is deterministic, in 0..1 and varies', () => {
    const values = points(200).map(hash3);
    for (const v of values) {
      expect(v).toBeGreaterThanOrEqual(0);
      expect(v).toBeLessThan(1);
    }
    expect(new Set(values.map((v) => v.toFixed(3))).size).toBeGreaterThan(150);
    expect(hash3([1, 2, 3])).toBe(hash3([1, 2, 3]));
  });
});

describe('wind displacement', () => {
  it('is exactly zero at strength 0 and with the wind off', () => {
    for (const p of points(100)) {
      for (const f of [frame({ strength: 0 }), frame({ enabled: false })]) {
        expect(effectiveStrength(f)).toBe(0);
        expect(displaceBark(p, f, twig)).toEqual(p);
        expect(displaceBark(p, f, null)).toEqual(p);
      }
    }
  });

  it('does not move the base of the trunk (or roots at ground level)', () => {
    const trunk: WindVertex = { ...twig, pivot: [0, 0, 0], level: 0, stiffness: 1 };
    for (let a = 0; a < 6.28; a += 0.3) {
      const p: Vec3 = [0.4 * Math.cos(a), 0, 0.4 * Math.sin(a)];
      const root: Vec3 = [3 * Math.cos(a), -0.05, 3 * Math.sin(a)];
      for (let t = 0; t < 10; t += 0.7) {
        expect(dist(displaceBark(p, frame({ time: t, strength: 2 }), trunk), p)).toBeLessThan(1e-9);
        expect(dist(displaceBark(root, frame({ time: t, strength: 2 }), null), root)).toBeLessThan(
          1e-9,
        );
      }
    }
  });

  it('moves tips more than the base (up the trunk and out along a branch)', () => {
    const f = frame({ strength: 1 });
    let previous = -1;
    for (let y = 0; y <= 17; y += 1) {
      const p: Vec3 = [0, y, 0];
      const d = dist(displaceBark(p, f, null), p);
      expect(d).toBeGreaterThan(previous);
      previous = d;
    }
    expect(previous).toBeGreaterThan(0.1); // a visible sway at the top of a 17 m tree
    expect(previous).toBeLessThan(17 * 0.15); // and no wild swing at strength 1
    // Along a level-3 twig: the twig bending grows from its pivot to its tip.
    const { pivot } = twig;
    const near: Vec3 = [pivot[0] + 0.02, pivot[1] + 0.01, pivot[2]];
    const tip: Vec3 = [pivot[0] + 0.6, pivot[1] + 0.3, pivot[2]];
    const swing = (p: Vec3) => dist(displaceBark(p, f, twig), displaceBark(p, f, null));
    let moved = 0;
    for (let t = 0; t < 6; t += 0.25) {
      const g = frame({ time: t });
      const a = dist(displaceBark(near, g, twig), displaceBark(near, g, null));
      const b = dist(displaceBark(tip, g, twig), displaceBark(tip, g, null));
      expect(b).toBeGreaterThanOrEqual(a);
      moved = Math.max(moved, b);
    }
    expect(moved).toBeGreaterThan(0.005);
    expect(swing(pivot)).toBeLessThan(1e-9); // the pivot itself stays on its parent
  });

  it('main bending keeps the distance from the tree base (renormalised length)', () => {
    for (const p of points(200)) {
      for (const s of [0.3, 1, 2.5]) {
        const q = mainBend(p, frame(), s);
        expect(len(q)).toBeCloseTo(len(p), 9);
      }
    }
    // And it really bends downwind at the top.
    const f = frame({ direction: [1, 0] });
    const top = mainBend([0, 17, 0], f, 1);
    expect(top[0]).toBeGreaterThan(0.1);
    expect(top[1]).toBeLessThan(17);
  });

  it('is continuous and smooth in time', () => {
    for (const p of points(60)) {
      for (let t = 0; t < 30; t += 0.37) {
        const a = displaceBark(p, frame({ time: t }), twig);
        const b = displaceBark(p, frame({ time: t + 1e-3 }), twig);
        const c = displaceBark(p, frame({ time: t + 1e-6 }), twig);
        // No jumps: bounded speed (under 10 m/s even for points far out on a whipping twig) ...
        expect(dist(a, c)).toBeLessThan(1e-5);
        // ... and 1 ms later a point of the crown moved by millimetres at most.
        expect(dist(a, b)).toBeLessThan(5e-3);
      }
    }
  });

  it('repeats with the period of its waves when gusts are off', () => {
    // With gust 0 every wave is a smooth triangle wave; their frequencies share no short period,
    // but each term is periodic: check the building block the shader uses for branch sway.
    const f = (t: number) => wave2(t * 0.375, t * 0.375 * 2);
    for (let t = 0; t < 10; t += 0.1) expect(f(t + 1 / 0.375)).toBeCloseTo(f(t), 9);
  });

  it('is continuous in space (no cracks at branch junctions)', () => {
    const f = frame({ strength: 2 });
    for (const p of points(100)) {
      const q: Vec3 = [p[0] + 1e-4, p[1] - 1e-4, p[2] + 1e-4];
      expect(dist(displaceBark(p, f, null), displaceBark(q, f, null))).toBeLessThan(1e-3);
    }
  });

  it('ignores vertex data that reads as GPU defaults (no distance from the root)', () => {
    const p: Vec3 = [3, 12, 1];
    const f = frame({ time: 0.8 });
    const defaults: WindVertex = {
      pivot: [0, 0, 0],
      level: 1,
      phase: 0,
      stiffness: 0,
      distance: 0,
      radius: 1,
    };
    expect(displaceBark(p, f, defaults)).toEqual(displaceBark(p, f, null));
    expect(displaceBark(p, f, twig)).not.toEqual(displaceBark(p, f, null));
  });

  it('changes with time when the wind blows', () => {
    const p: Vec3 = [3, 12, 1];
    const a = displaceBark(p, frame({ time: 0 }), twig);
    const b = displaceBark(p, frame({ time: 1.3 }), twig);
    expect(dist(a, b)).toBeGreaterThan(0.01);
  });
});

describe('leaves', () => {
  it('stay attached: the anchor moves exactly like a bark point there', () => {
    for (const a of points(50)) {
      for (let t = 0; t < 5; t += 1.1) {
        const f = frame({ time: t });
        expect(displaceAnchor(a, f)).toEqual(displaceBark(a, f, null));
      }
    }
  });

  it('flutter along the normal, zero at the leaf base, larger at the tip', () => {
    const n: Vec3 = [0, 0, 1];
    const anchor: Vec3 = [2, 10, -1];
    let tipMax = 0;
    for (let t = 0; t < 4; t += 0.1) {
      const f = frame({ time: t });
      expect(len(leafFlutter([0, 0, 0], n, anchor, f, 1))).toBe(0);
      const tip = leafFlutter([0, 1, 0], n, anchor, f, 1);
      expect(tip[0]).toBeCloseTo(0, 12);
      expect(tip[1]).toBeCloseTo(0, 12);
      tipMax = Math.max(tipMax, Math.abs(tip[2]));
      expect(Math.abs(tip[2])).toBeLessThanOrEqual(0.12 + 1e-9);
    }
    expect(tipMax).toBeGreaterThan(0.03);
    // Neighbouring leaves flutter out of phase.
    const f = frame({ time: 2 });
    const other = leafFlutter([0, 1, 0], n, [2.3, 10.4, -0.8], f, 1);
    expect(other[2]).not.toBeCloseTo(leafFlutter([0, 1, 0], n, anchor, f, 1)[2], 3);
  });
});
