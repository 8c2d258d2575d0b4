// The forest's trees are in the studio's Season: each unique tree's parameters carry the month
// the editor shows, and a forest opened without one keeps its presets' own (July).
import { describe, expect, it } from 'vitest';
import type { ReadyInfo } from 'sylva-trees/worker';
import { uniqueParams } from './ForestView';

const info = {
  registry: [
    { id: 'seed', kind: 'int', default: 1, min: 0, max: 4294967295, step: 1 },
    { id: 'season', kind: 'float', default: 7, min: 1, max: 12.99, step: 0.05 },
  ],
  presets: [
    { name: 'oak', label: 'Oak', description: '', leaf: 'oak', values: {} },
    { name: 'fir', label: 'Fir', description: '', leaf: 'fir', values: {} },
  ],
} as unknown as ReadyInfo;
const recipe = { count: 6, seed: 3, species: ['oak', 'fir'] };

describe('forest season', () => {
  it("gives every tree the editor's Season", () => {
    const trees = uniqueParams(info, recipe, 10.5);
    expect(trees.length).toBe(6);
    expect(trees.every((t) => t.params.season === 10.5)).toBe(true);
    // Each its own seed, whatever the month.
    expect(new Set(trees.map((t) => t.params.seed)).size).toBe(6);
    expect(uniqueParams(info, recipe).map((t) => t.params.seed)).toEqual(
      trees.map((t) => t.params.seed),
    );
  });

  it('keeps the presets’ own month without one', () => {
    expect(uniqueParams(info, recipe).every((t) => t.params.season !== 10.5)).toBe(true);
  });
});
