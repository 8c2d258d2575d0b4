// The house's front door stays short and true (rule 7): README.md under 250 lines with exactly the
// two commands, a code map naming every folder of core-rs/, web/src/ and the package's src/, and no dead link in
// README.md or docs/*.md (files, and #anchors into Markdown headings).
import assert from 'node:assert/strict';
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { githubSlug, links, sectionCode } from './readme.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const readme = readFileSync(join(root, 'README.md'), 'utf8');

const dirs = (dir) =>
  readdirSync(join(root, dir)).filter((name) => statSync(join(root, dir, name)).isDirectory());

test('README.md is at most 250 lines and shows exactly the two commands', () => {
  assert.ok(readme.split('\n').length <= 250, `${readme.split('\n').length} lines`);
  const commands = sectionCode(readme, 'The two commands')
    .split('\n')
    .filter((line) => line.trim() !== '')
    .map((line) => line.split('#')[0].trim());
  assert.deepEqual(commands, ['npm start', 'npm test']);
});

test('the code map names every folder of core-rs/, web/src/ and packages/sylva-trees/src/', () => {
  const map = sectionCode(readme, 'Code map');
  const wanted = [];
  for (const crate of dirs('core-rs')) {
    for (const sub of dirs(`core-rs/${crate}`)) {
      wanted.push(`${crate}/${sub}/`);
      if (sub === 'src') wanted.push(...dirs(`core-rs/${crate}/src`).map((d) => `src/${d}/`));
    }
  }
  // A folder of a crate's tests is named by its crate's tests/ line.
  const named = (entry) => map.includes(entry) || map.includes(entry.replace(/^[^/]+\//, ''));
  const missing = wanted.filter((entry) => !named(entry));
  for (const src of ['web/src', 'packages/sylva-trees/src']) {
    if (!map.includes(`${src}/ `)) missing.push(`${src}/`);
    for (const dir of dirs(src)) if (!map.includes(` ${dir}/ `)) missing.push(`${src}/${dir}/`);
  }
  assert.deepEqual(missing, []);
});

test('every relative link in README.md and docs/*.md leads somewhere', () => {
  const files = ['README.md', ...readdirSync(join(root, 'docs')).filter((f) => f.endsWith('.md'))];
  const broken = [];
  for (const file of files) {
    const path = file === 'README.md' ? join(root, file) : join(root, 'docs', file);
    for (const link of links(readFileSync(path, 'utf8'))) {
      if (/^[a-z]+:/i.test(link)) continue;
      const [target, anchor] = link.split('#');
      const resolved = target ? join(dirname(path), target) : path;
      if (!existsSync(resolved)) {
        broken.push(`${relative(root, path)}: ${link}`);
      } else if (anchor && resolved.endsWith('.md')) {
        const headings = readFileSync(resolved, 'utf8')
          .split('\n')
          .filter((line) => /^#{1,6} /.test(line))
          .map((line) => githubSlug(line.replace(/^#+ /, '')));
        if (!headings.includes(anchor))
          broken.push(`${relative(root, path)}: ${link} (no heading)`);
      }
    }
  }
  assert.deepEqual(broken, []);
});

test('githubSlug and links read Markdown as GitHub does', () => {
  assert.equal(
    githubSlug('Skeleton: Weber & Penn and the trunk'),
    'skeleton-weber--penn-and-the-trunk',
  );
  assert.equal(githubSlug('sylva bench-leaf'), 'sylva-bench-leaf');
  assert.equal(githubSlug('The `<sylva-tree>` element'), 'the-sylva-tree-element');
  assert.deepEqual(links('[a](x.md#y) ![p](i.png) `[not](code)` [b](https://e.org)'), [
    'x.md#y',
    'i.png',
    'https://e.org',
  ]);
});
