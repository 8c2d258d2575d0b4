import { describe, expect, it } from 'vitest';
import { CROWN_SHARE, placeForest, speciesMap, uniqueTrees, type PlacedTree } from './ecology';

const trees: PlacedTree[] = Array.from({ length: 16 }, (_, i) => ({
  id: i,
  species: i % 4,
  crown: 1.5 + (i % 5) * 0.7,
}));

/** Smallest margin `d − CROWN_SHARE (r_a + r_b)` over all pairs (≥ 0: the invariant holds). */
function worstMargin(layout: ReturnType<typeof placeForest>, list: PlacedTree[]): number {
  let worst = Infinity;
  for (let a = 0; a < layout.count; a++) {
    for (let b = a + 1; b < layout.count; b++) {
      const ra = list[layout.variety[a]!]!.crown * layout.scale[a]!;
      const rb = list[layout.variety[b]!]!.crown * layout.scale[b]!;
      const d = Math.hypot(layout.x[a]! - layout.x[b]!, layout.z[a]! - layout.z[b]!);
      worst = Math.min(worst, d - CROWN_SHARE * (ra + rb));
    }
  }
  return worst;
}

describe('placeForest', () => {
  it('keeps every two trunks as far apart as their crowns allow', () => {
    for (const seed of [1, 2, 99]) {
      const layout = placeForest(600, trees, { seed, species: 4 });
      expect(layout.count).toBe(600);
      expect(worstMargin(layout, trees)).toBeGreaterThanOrEqual(-1e-3);
    }
  });

  it('is the same for the same seed and trees, whatever order they arrived in', () => {
    const a = placeForest(300, trees, { seed: 7, species: 4 });
    const shuffled = [...trees].reverse();
    const b = placeForest(300, shuffled, { seed: 7, species: 4 });
    expect(b.count).toBe(a.count);
    for (let i = 0; i < a.count; i++) {
      expect(b.x[i]).toBe(a.x[i]);
      expect(shuffled[b.variety[i]!]!.id).toBe(trees[a.variety[i]!]!.id);
    }
    const c = placeForest(300, trees, { seed: 8, species: 4 });
    expect(Array.from(c.x.slice(0, 10))).not.toEqual(Array.from(a.x.slice(0, 10)));
  });

  it('puts each tree where the species map has its species', () => {
    const layout = placeForest(400, trees, { seed: 3, species: 4 });
    const map = speciesMap(3, 4);
    for (let i = 0; i < layout.count; i++) {
      expect(trees[layout.variety[i]!]!.species).toBe(map(layout.x[i]!, layout.z[i]!));
    }
  });

  it('places only generated trees, and nothing without any', () => {
    expect(placeForest(100, [], { seed: 1, species: 4 }).count).toBe(0);
    const some = trees.filter((t) => t.species === 2);
    const layout = placeForest(50, some, { seed: 1, species: 4 });
    expect(new Set(Array.from(layout.variety).map((v) => some[v]!.species))).toEqual(new Set([2]));
  });
});

describe('uniqueTrees', () => {
  it('gives every species a tree, each tree its own seed, the same for the same seed', () => {
    const a = uniqueTrees(16, 4, 5);
    expect(a).toHaveLength(16);
    expect(new Set(a.map((t) => t.species))).toEqual(new Set([0, 1, 2, 3]));
    expect(new Set(a.map((t) => t.seed)).size).toBe(16);
    expect(uniqueTrees(16, 4, 5)).toEqual(a);
    expect(uniqueTrees(16, 4, 6)).not.toEqual(a);
    expect(uniqueTrees(64, 3, 1)).toHaveLength(64);
  });
});
