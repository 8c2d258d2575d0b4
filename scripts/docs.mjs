// `npm run docs`: regenerates the README's parameter reference from the registry
// (`sylva params --markdown`). A Rust test fails when the README is stale.
import { execFileSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));
const table = execFileSync(
  'cargo',
  ['run', '--quiet', '--release', '-p', 'sylva-cli', '--', 'params', '--markdown'],
  {
    cwd: root,
    encoding: 'utf8',
  },
).trim();
const path = `${root}/README.md`;
const readme = readFileSync(path, 'utf8');
const start = '<!-- params:start -->';
const end = '<!-- params:end -->';
const a = readme.indexOf(start);
const b = readme.indexOf(end);
if (a < 0 || b < a) throw new Error('README.md lacks the params:start/params:end markers');
writeFileSync(path, `${readme.slice(0, a + start.length)}\n${table}\n${readme.slice(b)}`);
console.log('README.md parameter reference updated');
