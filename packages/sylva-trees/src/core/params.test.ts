/** Tests of the registry helpers: snapping, normalisation, presets, grouping, seeds. */
import { describe, expect, it } from 'vitest';
import type { ParamSpec } from './types';
import {
  applyPreset,
  decimalsOf,
  defaultParams,
  displayValue,
  firstStage,
  groupParams,
  matchingPreset,
  normalizeValue,
  randomSeed,
  snapToStep,
} from './params';
import { realPresets, realRegistry } from '../testing/realWasm';

const float: ParamSpec = {
  id: 'l1_length',
  group: 'A',
  label: 'Length',
  kind: 'float',
  default: 0.30000001192092896,
  min: 0,
  max: 2,
  step: 0.01,
  unit: '',
  description: '',
};

describe('params helpers', () => {
  it('counts decimals', () => {
    expect(decimalsOf(0.01)).toBe(2);
    expect(decimalsOf(1e-7)).toBe(7);
    expect(decimalsOf(5)).toBe(0);
  });

  it('snaps to the grid without noise and clamps', () => {
    expect(snapToStep(float, 0.1 + 0.2 + 0.05)).toBe(0.35);
    expect(snapToStep(float, 0.123)).toBe(0.12);
    expect(snapToStep(float, 9)).toBe(2);
    expect(snapToStep(float, -1)).toBe(0);
  });

  it('snaps onto an f32-noisy default', () => {
    expect(snapToStep(float, 0.3)).toBe(float.default);
    expect(normalizeValue(float, 0.3)).toBe(float.default);
  });

  it('normalisation keeps off-grid values and is idempotent', () => {
    expect(normalizeValue(float, 0.333)).toBe(0.333);
    for (const v of [0.333, 0.35, 0.1 + 0.2, 1.999, 0, -0, 2]) {
      const once = normalizeValue(float, v);
      expect(normalizeValue(float, once)).toBe(once);
    }
    expect(Object.is(normalizeValue(float, -0), 0)).toBe(true);
  });

  it('displays values at the step precision', () => {
    expect(displayValue(float, float.default)).toBe('0.3');
    expect(displayValue(float, 0.333)).toBe('0.333');
  });

  it('random seeds stay within range and are integers', () => {
    const seed = realRegistry().find((s) => s.id === 'seed');
    expect(seed).toBeDefined();
    if (!seed) return;
    for (const r of [0, 0.5, 0.999999999]) {
      const v = randomSeed(seed, () => r);
      expect(Number.isInteger(v)).toBe(true);
      expect(v).toBeGreaterThanOrEqual(seed.min);
      expect(v).toBeLessThanOrEqual(seed.max);
    }
  });

  it('groups keep registry order', () => {
    const registry = realRegistry();
    const groups = groupParams(registry).map(([g]) => g);
    const firstSeen = registry.map((s) => s.group).filter((g, i, a) => a.indexOf(g) === i);
    expect(groups).toEqual(firstSeen);
  });

  it('a preset applied to defaults is recognised as that preset', () => {
    const registry = realRegistry();
    const presets = realPresets();
    for (const preset of presets) {
      const params = applyPreset(registry, preset);
      const match = matchingPreset(registry, presets, params);
      expect(match).toBeDefined();
      expect(applyPreset(registry, match ?? preset)).toEqual(params);
    }
  });
});

describe('firstStage', () => {
  const reg = realRegistry();
  const base = defaultParams(reg);
  it('is the earliest stage among the changed parameters, null when none changed', () => {
    expect(firstStage(reg, base, { ...base })).toBeNull();
    expect(firstStage(reg, base, { ...base, show_preview: 1 })).toBe('viewer');
    expect(firstStage(reg, base, { ...base, leaf_teeth: 3 })).toBe('leaf');
    expect(firstStage(reg, base, { ...base, leaf_teeth: 3, foliage_angle: 10 })).toBe('foliage');
    expect(firstStage(reg, base, { ...base, mesh_quality: 2, foliage_angle: 10 })).toBe('mesh');
    expect(firstStage(reg, base, { ...base, l1_branches: 9, show_markers: 1 })).toBe('skeleton');
  });
  it('every registry parameter declares its stage', () => {
    const stages = new Set(reg.map((s) => s.stage));
    expect([...stages].sort()).toEqual(['foliage', 'leaf', 'mesh', 'skeleton', 'viewer']);
    expect(reg.every((s) => s.stage !== undefined)).toBe(true);
    expect(reg.filter((s) => s.stage === 'viewer').map((s) => s.id)).toEqual(
      expect.arrayContaining(['show_preview', 'show_markers', 'show_volumes']),
    );
  });
});
