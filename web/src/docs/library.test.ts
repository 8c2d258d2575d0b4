/**
 * The docs page's package section: its table names the calls its example makes. (That the
 * package has every member named is a type check: `Member` is typed against its exports.)
 */
import { describe, expect, it } from 'vitest';
import { LIBRARY_API, LIBRARY_EXAMPLE } from './library';

describe('the docs page on sylva-trees', () => {
  it('shows each call as written in its row', () => {
    const members = LIBRARY_API.flatMap((r) => r.members);
    expect(members.length).toBeGreaterThan(10);
    for (const row of LIBRARY_API) {
      for (const m of row.members) expect(row.call).toContain(m.replace(/^SylvaTree\./, ''));
    }
  });

  it("shows the issue's API in its example, every call documented in the table", () => {
    const calls = [...LIBRARY_EXAMPLE.matchAll(/\b(tree|SylvaTree)\.(\w+)/g)].map(
      ([, owner, name]) => `${owner}.${name}`,
    );
    expect(calls).toEqual(
      expect.arrayContaining(['SylvaTree.create', 'tree.object', 'tree.update', 'tree.set']),
    );
    expect(calls).toEqual(expect.arrayContaining(['tree.stats', 'tree.toGLB', 'tree.dispose']));
    const documented = new Set<string>(LIBRARY_API.flatMap((r) => r.members));
    for (const c of calls) expect(documented.has(c), c).toBe(true);
    expect(LIBRARY_EXAMPLE).toContain("from 'sylva-trees'");
  });
});
