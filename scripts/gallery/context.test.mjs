// `--only SECTION_ID` rewrites only its section of docs/gallery.md: updateSections replaces a
// section in place, puts a new one where the section order has it, and leaves the rest byte for
// byte as the full page's markdown wrote it.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { markdown, updateSections } from './context.mjs';

const section = (id, title, rows) => ({
  section: { id, title, intro: `${title} intro.`, layout: (shots) => shots.map((s) => `| ${s} |`) },
  shots: rows,
});
const a = section('a', 'A', ['a1', 'a2']);
const b = section('b', 'B', ['b1']);
const c = section('c', 'C', ['c1']);
const order = [a, b, c].map((d) => d.section);

test('an unchanged section list gives the page back byte for byte', () => {
  const page = markdown([a, b, c]);
  assert.equal(updateSections(page, [], order), page);
  assert.equal(updateSections(page, [b], order), page);
});

test('a section rendered again replaces only its own part', () => {
  const page = markdown([a, b, c]);
  const b2 = section('b', 'B', ['new1', 'new2']);
  assert.equal(updateSections(page, [b2], order), markdown([a, b2, c]));
});

test('a new section goes where the section order has it', () => {
  assert.equal(updateSections(markdown([a, c]), [b], order), markdown([a, b, c]));
  assert.equal(updateSections(markdown([a, b]), [c], order), markdown([a, b, c]));
});
