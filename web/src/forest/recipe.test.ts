import { describe, expect, it } from 'vitest';
import { decodeRecipe, DEFAULT_UNIQUE, encodeRecipe, MAX_UNIQUE } from './recipe';

const KNOWN = ['quaking_aspen', 'fir', 'oak', 'cypress', 'willow'];
const DEFAULTS = ['quaking_aspen', 'fir', 'oak', 'cypress'];

describe('forest recipe', () => {
  it('round-trips through the link text', () => {
    const recipe = { count: 24, seed: 4_000_000_000, species: ['fir', 'willow'] };
    const text = encodeRecipe(recipe);
    expect(text).toBe('24:4000000000:fir,willow');
    expect(decodeRecipe(text, KNOWN, DEFAULTS)).toEqual({ recipe, notices: [] });
  });

  it('is the defaults without an entry', () => {
    const { recipe, notices } = decodeRecipe(null, KNOWN, DEFAULTS);
    expect(recipe).toEqual({ count: DEFAULT_UNIQUE, seed: 1, species: DEFAULTS });
    expect(notices).toEqual([]);
  });

  it('falls back part by part on hostile values, with a notice for each', () => {
    for (const [text, count, seed, species] of [
      ['0:5:fir', DEFAULT_UNIQUE, 5, ['fir']],
      [`${MAX_UNIQUE + 1}:5:fir`, DEFAULT_UNIQUE, 5, ['fir']],
      ['-3:-1:fir', DEFAULT_UNIQUE, 1, ['fir']],
      ['1e3:99999999999:fir', DEFAULT_UNIQUE, 1, ['fir']],
      ['8:2:<script>,oak', 8, 2, ['oak']],
      ['8:2:nothing', 8, 2, DEFAULTS],
    ] as const) {
      const { recipe, notices } = decodeRecipe(text, KNOWN, DEFAULTS);
      expect(recipe, text).toEqual({ count, seed, species });
      expect(notices.length, text).toBeGreaterThan(0);
    }
    expect(decodeRecipe('x'.repeat(5000), KNOWN, DEFAULTS).notices[0]).toContain('5000');
    expect(decodeRecipe(`${MAX_UNIQUE}:0:fir,fir,oak`, KNOWN, DEFAULTS).recipe).toEqual({
      count: MAX_UNIQUE,
      seed: 0,
      species: ['fir', 'oak'],
    });
  });
});
