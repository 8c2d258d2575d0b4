/** The docs page's reference model, built from the real registry. */
import { describe, expect, it } from 'vitest';
import { groupParams, type ParamSpec } from 'sylva-trees/core';
import { realPresets, realRegistry } from 'sylva-trees/testing';
import { anchorOf, buildDocsModel, defaultText, rangeText } from './model';

const registry = realRegistry();

describe('buildDocsModel', () => {
  const model = buildDocsModel(registry, realPresets());

  it('lists every registry parameter once, grouped in panel order', () => {
    expect(model.count).toBe(registry.length);
    const ids = model.groups.flatMap((g) => g.params.map((p) => p.id));
    expect(ids).toEqual(groupParams(registry).flatMap(([, specs]) => specs.map((s) => s.id)));
    expect(new Set(ids).size).toBe(registry.length);
    expect(model.groups.map((g) => g.name)).toEqual(groupParams(registry).map(([n]) => n));
    expect(new Set(model.groups.map((g) => g.anchor)).size).toBe(model.groups.length);
  });

  it('copies label, unit and description from the registry', () => {
    const rows = new Map(model.groups.flatMap((g) => g.params).map((p) => [p.id, p]));
    for (const spec of registry) {
      const row = rows.get(spec.id);
      expect(row?.label).toBe(spec.label);
      expect(row?.unit).toBe(spec.unit);
      expect(row?.description).toBe(spec.description);
      expect(row?.description.length, spec.id).toBeGreaterThan(0);
    }
    expect(model.presets.map((p) => p.name)).toContain('quaking_aspen');
  });
});

describe('display text', () => {
  const spec = (over: Partial<ParamSpec>): ParamSpec => ({
    id: 'ratio',
    group: 'G',
    label: 'X',
    kind: 'float',
    default: 0.014999999664723873,
    min: 0.001,
    max: 0.2,
    step: 0.001,
    unit: '',
    description: '',
    ...over,
  });

  it('floats hide f32 noise; ranges carry the step', () => {
    expect(defaultText(spec({}))).toBe('0.015');
    expect(rangeText(spec({}))).toBe('0.001 – 0.2, step 0.001');
    expect(rangeText(spec({ kind: 'int', min: 1, max: 4, step: 1, default: 3 }))).toBe('1 – 4');
  });

  it('enums name their options, bools say on/off', () => {
    const e = spec({ kind: 'enum', default: 1, min: 0, max: 2, step: 1, options: ['A', 'B', 'C'] });
    expect(defaultText(e)).toBe('1 (B)');
    expect(rangeText(e)).toBe('0 A, 1 B, 2 C');
    const b = spec({ kind: 'bool', default: 0, min: 0, max: 1, step: 1 });
    expect(defaultText(b)).toBe('0 (off)');
    expect(rangeText(b)).toBe('0 or 1');
  });

  it('anchors are stable slugs', () => {
    expect(anchorOf('Level 1')).toBe('group-level-1');
    expect(anchorOf('Growth Volume')).toBe('group-growth-volume');
  });
});
