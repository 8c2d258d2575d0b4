import { describe, expect, it } from 'vitest';
import {
  HYSTERESIS,
  IMPOSTOR_LEVEL,
  screenFraction,
  selectLod,
  switchDistances,
  VIEWER_THRESHOLDS,
} from './selection';

describe('LOD selection', () => {
  it('screen fraction is 1 when the sphere fills the view height', () => {
    const fov = 40;
    const d = 5 / Math.tan((fov * Math.PI) / 360);
    expect(screenFraction(5, d, fov)).toBeCloseTo(1, 12);
    expect(screenFraction(5, 2 * d, fov)).toBeCloseTo(0.5, 12);
  });

  it('walks LOD0 → 1 → 2 → impostor as the tree shrinks, and back', () => {
    const seen: number[] = [];
    let level = 0;
    for (let s = 1.2; s > 0.05; s *= 0.97) {
      level = selectLod(level, s);
      if (seen[seen.length - 1] !== level) seen.push(level);
    }
    expect(seen).toEqual([0, 1, 2, IMPOSTOR_LEVEL]);
    const back: number[] = [];
    for (let s = 0.05; s < 1.2; s *= 1.03) {
      level = selectLod(level, s);
      if (back[back.length - 1] !== level) back.push(level);
    }
    expect(back).toEqual([IMPOSTOR_LEVEL, 2, 1, 0]);
  });

  it('holds the level inside the hysteresis band', () => {
    const t = VIEWER_THRESHOLDS[0]!;
    // Just under the threshold but inside the band: LOD0 stays, LOD1 stays.
    expect(selectLod(0, t * (1 - HYSTERESIS / 2))).toBe(0);
    expect(selectLod(1, t * (1 + HYSTERESIS / 2))).toBe(1);
    // Beyond the band it switches.
    expect(selectLod(0, t * (1 - HYSTERESIS * 1.5))).toBe(1);
    expect(selectLod(1, t * (1 + HYSTERESIS * 1.5))).toBe(0);
    // Oscillating around a threshold by less than the band never pops.
    let level = 0;
    let switches = 0;
    for (let k = 0; k < 100; k++) {
      const s = t * (1 + 0.08 * Math.sin(k));
      const next = selectLod(level, s);
      if (next !== level) switches++;
      level = next;
    }
    expect(switches).toBe(0);
  });

  it('jumps several levels at once and clamps odd inputs', () => {
    expect(selectLod(0, 0.01)).toBe(IMPOSTOR_LEVEL);
    expect(selectLod(IMPOSTOR_LEVEL, 5)).toBe(0);
    expect(selectLod(-3, 5)).toBe(0);
    expect(selectLod(9, 0.01)).toBe(IMPOSTOR_LEVEL);
    expect(selectLod(0, 0.4, [0.5, 0.3, 0.2], 0)).toBe(1);
  });

  it('switch distances agree with the screen-fraction thresholds', () => {
    const fov = 40;
    const { out, back } = switchDistances(VIEWER_THRESHOLDS, fov);
    VIEWER_THRESHOLDS.forEach((t, k) => {
      expect(screenFraction(1, out[k]!, fov)).toBeCloseTo(t * (1 - HYSTERESIS), 12);
      expect(screenFraction(1, back[k]!, fov)).toBeCloseTo(t * (1 + HYSTERESIS), 12);
      expect(out[k]!).toBeGreaterThan(back[k]!);
    });
  });
});
