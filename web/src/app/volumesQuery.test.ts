/** Regression: writing `vol=` must not re-encode the rest of a hostile share link. */
import { describe, expect, it } from 'vitest';
import { withVolumesQuery } from './useGrowthEditor';

describe('withVolumesQuery', () => {
  it('keeps every other entry byte for byte (a bad %-escape stays bad)', () => {
    // Re-serialising with URLSearchParams turned `%ZZ` into `%25ZZ`: the app then read a valid,
    // unknown key and the "malformed entry" notice of the link was lost (a startup race).
    expect(withVolumesQuery('?v=1&%ZZ=1&seed=5', '')).toBe('?v=1&%ZZ=1&seed=5');
    expect(withVolumesQuery('?v=1&seed=%E0%A4%A', '')).toBe('?v=1&seed=%E0%A4%A');
  });

  it('replaces or removes only the vol entry', () => {
    expect(withVolumesQuery('?v=1&vol=old&seed=5', '1;s:c:0,1,2,3')).toBe(
      '?v=1&seed=5&vol=1%3Bs%3Ac%3A0%2C1%2C2%2C3',
    );
    expect(withVolumesQuery('?v=1&vol=old&seed=5', '')).toBe('?v=1&seed=5');
    expect(withVolumesQuery('?vol=x', '')).toBe('');
    expect(withVolumesQuery('', '1;s:c:0,0,0,1')).toBe('?vol=1%3Bs%3Ac%3A0%2C0%2C0%2C1');
  });
});
