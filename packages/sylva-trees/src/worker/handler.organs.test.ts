/**
 * Organ sets (flowers, fruit, catkins, buds) through the worker handler and the real wasm: the
 * tree message carries them with the placements, their arrays transferred, consistent with
 * their counts; edits that move no placement send none; July sends an empty list.
 */
import { describe, expect, it } from 'vitest';
import { realPresets } from '../testing/realWasm';
import { harness } from '../testing/workerHarness';
import type { Params } from '../core/types';
import { meanTint } from './organs';

/** The oak preset bearing acorns (Fruit 1 = Acorns) in `season`. */
function oak(season: number): Params {
  const preset = realPresets().find((p) => p.name === 'oak');
  if (!preset) throw new Error('no oak preset');
  return { ...preset.values, fruit: 1, season };
}

describe('organ sets in the tree message', () => {
  it('an oak in September sends its acorns, cups and stalks, transferred', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: oak(9.5) });
    const result = h.lastResult();
    const organs = result.organs ?? [];
    expect(organs.map((o) => o.name).sort()).toEqual(['acorn cups', 'acorn stalks', 'acorns']);
    const transfer = h.sent.find((s) => s.message === result)?.transfer ?? [];
    for (const set of organs) {
      const count = set.colors.length / 3;
      expect(count, set.name).toBeGreaterThan(10);
      expect(set.matrices.length).toBe(count * 16);
      expect(set.positions.length % 3).toBe(0);
      expect(set.normals.length).toBe(set.positions.length);
      expect(set.indices.length % 3).toBe(0);
      expect(Math.max(...set.indices)).toBeLessThan(set.positions.length / 3);
      expect(set.color.every((c) => c >= 0 && c <= 1)).toBe(true);
      expect(set.roughness).toBeGreaterThan(0);
      for (const a of [set.positions, set.normals, set.indices, set.matrices, set.colors]) {
        expect(transfer).toContain(a.buffer);
      }
    }
    expect(organs.find((o) => o.name === 'acorns')?.kind).toBe('fruit');
    // Acorns, cups and stalks pair up: one of each per acorn.
    expect(new Set(organs.map((o) => o.colors.length)).size).toBe(1);
    // The merged tree keeps them.
    expect(h.tree().organs?.length).toBe(3);
  });

  it('sends organs only with new placements, and none for July', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: oak(9.5) });
    // A viewer-only edit moves nothing: no organ list, the merged tree keeps the old one.
    h.handle({ type: 'generate', id: 2, params: { ...oak(9.5), show_preview: 1 } });
    expect(h.lastResult().organs).toBeUndefined();
    expect(h.tree().organs?.length).toBe(3);
    // More fruit: new placements, new sets.
    h.handle({ type: 'generate', id: 3, params: { ...oak(9.5), fruit_load: 0.8 } });
    const more = h.lastResult().organs ?? [];
    expect(more.length).toBe(3);
    expect(more[0]!.colors.length).toBeGreaterThan(
      (h.results()[0]!.organs ?? [])[0]!.colors.length,
    );
    // July: the placements change and the list is empty.
    h.handle({ type: 'generate', id: 4, params: { ...oak(7.5), fruit_load: 0.8 } });
    expect(h.lastResult().organs).toEqual([]);
    expect(h.tree().organs).toEqual([]);
  });

  it('a bare tree in January carries buds and its leaves lie on the ground', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: { season: 1.5 } });
    const organs = h.lastResult().organs ?? [];
    expect(organs.map((o) => o.kind)).toEqual(['bud']);
    expect(organs[0]!.colors.length / 3).toBeGreaterThan(50);
    const meta = h.tree().meta;
    // Every leaf lies on the ground: the instances' heights are near 0.
    const m = h.tree().foliage?.matrices ?? new Float32Array(0);
    expect(m.length / 16).toBeGreaterThan(100);
    let high = 0;
    for (let i = 13; i < m.length; i += 16) if (m[i]! > 0.5) high++;
    expect(high, JSON.stringify(meta.leaves)).toBe(0);
  });
});

describe('the leaves on the tree: their Season tint', () => {
  it('is the mean tint of the leaves on the tree, leaving the fallen ones out', () => {
    const mean = meanTint(new Float32Array([1, 1, 1, 0.5, 0.25, 0.125, 9, 9, 9]), 2);
    expect(mean).toEqual([0.75, 0.625, 0.5625]);
    expect(meanTint(new Float32Array([1, 1, 1]), 0)).toBeNull();
  });

  it('is about 1 in July, yellow in October and absent in January', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: { season: 7.5 } });
    const july = h.lastResult().leafTint;
    h.handle({ type: 'generate', id: 2, params: { season: 10.3 } });
    const october = h.lastResult().leafTint;
    h.handle({ type: 'generate', id: 3, params: { season: 1.5 } });
    const january = h.lastResult().leafTint;
    if (!july || !october) throw new Error('no tint');
    // July: the summer crown, grey (the crown's shade darkens every channel alike).
    expect(Math.min(...july) / Math.max(...july)).toBeGreaterThan(0.85);
    expect(Math.max(...july)).toBeLessThan(1.2);
    // October (the default tree wears the aspen's calendar): golden, far more red than blue.
    expect(october[0]).toBeGreaterThan(2 * october[2]);
    // January: every leaf has fallen.
    expect(january).toBeNull();
    expect(h.tree().leafTint).toBeNull();
  });
});
