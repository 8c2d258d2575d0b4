/**
 * Every hostile share link of the table through the app's own load path (the page's query as
 * the browser's URL parser leaves it, then `loadInitialParams` with empty storage): the notice
 * or silence it must give, inert text in every message, and the params of the equivalent clean
 * link. The e2e test opens the cases marked `browser` in Chromium.
 */
import { describe, expect, it } from 'vitest';
import { loadInitialParams } from '../app/persistence';
import { realRegistry } from 'sylva-trees/testing';
import { DEFAULT, HOSTILE, SEED5 } from './hostileLinks.fixture';
import { editsFromSearch } from './useHandEdits';

const registry = realRegistry();

/** What `location.search` is for a link: the WHATWG URL parser drops the fragment and escapes. */
const searchOf = (query: string) => new URL(`/${query}`, 'https://sylva.example').search;

/** What the app loads from a link: the params, the hand edits and every notice. */
const load = (query: string) => {
  const search = searchOf(query);
  const initial = loadInitialParams(registry, search, null);
  const edits = editsFromSearch(search);
  return {
    params: initial.params,
    edits: edits.edits,
    messages: [...initial.messages, ...edits.messages],
  };
};

describe('hostile share links through the load path', () => {
  it('the table is large and the reference trees differ', () => {
    expect(HOSTILE.length).toBeGreaterThanOrEqual(30);
    expect(load(SEED5).params).not.toEqual(load(DEFAULT).params);
    expect(HOSTILE.filter((c) => c.browser).length).toBeGreaterThanOrEqual(10);
  });

  for (const c of HOSTILE) {
    it(`${c.name}: ${c.notice ? 'a notice' : 'silence'} and the tree of ${c.same}`, () => {
      const result = load(c.query);
      expect(result.params).toEqual(load(c.same).params);
      expect(result.edits).toEqual(load(c.same).edits);
      if (c.notice) {
        expect(
          result.messages.some((m) => c.notice!.test(m)),
          result.messages.join('\n'),
        ).toBe(true);
      } else {
        expect(result.messages).toEqual([]);
      }
      for (const m of result.messages) {
        // eslint-disable-next-line no-control-regex -- the characters the banner must not show
        expect(m).not.toMatch(/[\u0000-\u0008\u200b-\u200f\u202a-\u202e]/);
        expect(m.length).toBeLessThan(400);
      }
    });
  }
});
