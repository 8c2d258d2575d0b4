// `npm run docs`: regenerates the references that come from the code. A Rust test
// (core-rs/sylva-cli/tests/docs.rs) fails when a file differs from what the CLI prints.
//   docs/parameters.md      `sylva params --markdown`   (the parameter registry)
//   docs/cli.md             `sylva cli-reference`       (the CLI's clap declarations)
//   web/src/docs/cli.json   `sylva cli-reference --json` (the docs page's Command line section)
//   packages/sylva-trees/src/core/generated/params.ts   `sylva params --typescript` (ParamId,
//                           PresetId, the registry and the presets as TypeScript)
//   packages/sylva-trees/src/core/generated/payloads.ts `sylva params --payloads` (the JSON
//                           the core returns beside the buffers, as TypeScript interfaces)
//   core-rs/sylva-py/python/sylva_trees/__init__.pyi     `sylva params --python-stub` (the Python
//                           package's type stub: Params, PresetName, ParamId, Tree, generate)
import { execFileSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { nativeCli } from './native-cli.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const sylva = nativeCli();
const outputs = [
  ['docs/parameters.md', ['params', '--markdown']],
  ['docs/cli.md', ['cli-reference']],
  ['web/src/docs/cli.json', ['cli-reference', '--json']],
  ['packages/sylva-trees/src/core/generated/params.ts', ['params', '--typescript']],
  ['packages/sylva-trees/src/core/generated/payloads.ts', ['params', '--payloads']],
  ['core-rs/sylva-py/python/sylva_trees/__init__.pyi', ['params', '--python-stub']],
];
for (const [file, args] of outputs) {
  writeFileSync(`${root}/${file}`, execFileSync(sylva, args, { encoding: 'utf8' }));
  console.log(`${file} written (sylva ${args.join(' ')})`);
}
