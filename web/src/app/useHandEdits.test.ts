/** The edit list as the tools extend it, and its share-link text (or none when too long). */
import { describe, expect, it } from 'vitest';
import { MAX_EDITS_LINK_LENGTH } from 'sylva-trees/url';
import type { Edit } from 'sylva-trees/core';
import { appendEdit, dateEdit, editsFromSearch, linkText } from './useHandEdits';

const cut: Edit = { op: 'cut', at: [1, 4, 0] };
const crown = (h: number): Edit => ({
  op: 'crown',
  outline: [
    [0, 2],
    [2, h / 2],
    [0, h],
  ],
});

describe('the tools’ edit list', () => {
  it('appends edits in order; a new crown outline replaces the previous one', () => {
    const list = appendEdit(appendEdit(appendEdit([], crown(8)), cut), crown(9));
    expect(list).toEqual([cut, crown(9)]);
    expect(appendEdit(list, cut)).toEqual([cut, crown(9), cut]);
  });

  it('a cut made now carries the tree’s Age as its year (whole years); other edits do not', () => {
    expect(dateEdit(cut, { age: 37.6 })).toEqual({ ...cut, year: 38 });
    expect(dateEdit({ ...cut, year: 12 }, { age: 37.6 })).toEqual({ ...cut, year: 12 });
    expect(dateEdit(crown(8), { age: 37.6 })).toEqual(crown(8));
    expect(dateEdit(cut, {})).toEqual(cut);
    expect(dateEdit(cut, null)).toEqual(cut);
    expect(linkText([dateEdit(cut, { age: 40 })])).toBe('1~c100.400.0.40');
  });

  it('the share link carries the list, or nothing when it is too long (never a part)', () => {
    const text = linkText([cut]);
    expect(text).toBe('1~c100.400.0');
    expect(editsFromSearch(`?v=1&e=${text}`)).toEqual({ edits: [cut], messages: [] });
    const stroke: Edit = {
      op: 'paint',
      points: Array.from({ length: 200 }, (_, k) => [k * 0.37, 5 + (k % 7) * 0.21, 0]),
      radius: 0.6,
      density: 400,
      segment: 0.25,
      kill: 0.4,
    };
    const long = [stroke, stroke, stroke];
    expect(linkText(long)).toBeNull();
    expect(linkText([stroke])?.length).toBeLessThanOrEqual(MAX_EDITS_LINK_LENGTH);
  });
});
