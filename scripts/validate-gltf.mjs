// `node scripts/validate-gltf.mjs [--preset NAME]... [--keep DIR]`: exports every preset as GLB
// through the native CLI (`sylva generate --preset NAME --out FILE.glb --leaves MODE`), in both
// leaf modes (instanced, baked), and validates each file with the Khronos glTF Validator
// (npm `gltf-validator`, `validateBytes`), and the file for strict importers (`--strict`), which
// must also list no extension at all (no `extensionsUsed`, no `extensionsRequired`). Prints one line per file with the error, warning and
// info counts and the messages of any error or warning; exits 1 if any file has an error or a
// warning (both kinds must pass with none).
// Infos are expected for instanced leaves: the validator does not implement
// EXT_mesh_gpu_instancing, says so (UNSUPPORTED_EXTENSION) and sees its accessors as unused.
//
// The default tree's levels-of-detail GLB (`--lods`), default and strict, passes the same way,
// and so do the growth-animation GLBs (`--growth-animation`: morph targets and an animation) of
// the default tree and of one grown preset (grown_broadleaf), which must hold one animation
// whose last key time is the tree's Age.
//
// Also the default tree with a main branch cut (`--edits`, [`CUT`]): its GLB has the third
// material, `cut_face` (the end grain); and trees with flowers, fruit, catkins and buds (the
// Season): the default tree in January (buds, fallen leaves), the oak bearing acorns in
// September, the quaking aspen's catkins in March.
//
// Then, when the wasm build exists (packages/sylva-trees/src/wasm), checks that the wasm exporters (`to_glb`,
// `to_glb_file`) write the same bytes as the native one (default tree, with and without the cut,
// both leaf modes and strict), and `to_growth_glb_file` the same growth GLB.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { validateBytes } from 'gltf-validator';
import { nativeCli } from './native-cli.mjs';

const args = process.argv.slice(2);
const only = args.flatMap((a, i) => (a === '--preset' ? [args[i + 1]] : []));
const keepAt = args.indexOf('--keep');
const dir = keepAt >= 0 ? args[keepAt + 1] : mkdtempSync(join(tmpdir(), 'sylva-gltf-'));

const sylva = nativeCli();
const presets = JSON.parse(
  execFileSync(sylva, ['presets'], { encoding: 'utf8', maxBuffer: 1 << 26 }),
)
  .map((p) => p.name)
  .filter((n) => only.length === 0 || only.includes(n));

/** A cut on a main branch of the default tree, 0.6 m out from the trunk (docs/formats.md). */
const CUT = { op: 'cut', at: [-0.19, 5.94, 0.59] };
const editsFile = join(dir, 'cut-edits.json');
writeFileSync(editsFile, JSON.stringify({ version: 1, edits: [CUT] }));
/** `[label, CLI arguments]` of every tree exported. */
const trees = presets.map((name) => [name, ['--preset', name]]);
if (only.length === 0 || only.includes('default')) {
  trees.push(['default + cut', ['--edits', editsFile]]);
  // January: winter buds at the shoot tips and the fallen leaves on the ground.
  trees.push(['default January', ['--set', 'season=1.5']]);
}
// Seasons with flowers and fruit: one material, mesh and node per organ set.
if (only.length === 0 || only.includes('oak')) {
  trees.push([
    'oak September acorns',
    ['--preset', 'oak', '--set', 'fruit=1', '--set', 'season=9.5'],
  ]);
}
if (only.length === 0 || only.includes('quaking_aspen')) {
  trees.push(['quaking_aspen March catkins', ['--preset', 'quaking_aspen', '--set', 'season=3.2']]);
}

let failed = 0;
let warnings = 0;
const mb = (n) => (n / 1e6).toFixed(1).padStart(6);
console.log('preset              leaves      size MB  errors warnings infos');
/** The extensions a GLB's JSON chunk lists as used or required. */
function extensionsOf(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const json = JSON.parse(
    new TextDecoder().decode(bytes.subarray(20, 20 + view.getUint32(12, true))),
  );
  return [...(json.extensionsUsed ?? []), ...(json.extensionsRequired ?? [])];
}

/** The export modes: `[label, CLI arguments]`. */
const MODES = [
  ['instanced', ['--leaves', 'instanced']],
  ['baked', ['--leaves', 'baked']],
  ['strict', ['--strict']],
];
for (const [name, treeArgs] of trees) {
  for (const [leaves, modeArgs] of MODES) {
    const file = join(dir, `${name.replace(/\W+/g, '-')}-${leaves}.glb`);
    execFileSync(sylva, ['generate', ...treeArgs, ...modeArgs, '--out', file], {
      stdio: 'ignore',
    });
    const bytes = new Uint8Array(readFileSync(file));
    if (keepAt < 0) rmSync(file);
    const report = await validateBytes(bytes, { maxIssues: 100 });
    const { numErrors, numWarnings, numInfos } = report.issues;
    if (numErrors > 0 || numWarnings > 0) failed++;
    // The strict file lists no extension at all.
    const extensions = extensionsOf(bytes);
    if (leaves === 'strict' && extensions.length > 0) {
      failed++;
      console.log(`    ${name}: the strict GLB lists extensions ${extensions.join(', ')}`);
    }
    // The cut tree's third material: the cut faces' end grain.
    const materials = report.info?.materialCount;
    if (treeArgs.includes('--edits') && materials !== 3) {
      failed++;
      console.log(`    ${name}: ${materials} materials, expected 3 (bark, leaves, cut_face)`);
    }
    warnings += numWarnings;
    console.log(
      `${name.padEnd(19)} ${leaves.padEnd(10)} ${mb(bytes.length)}  ${String(numErrors).padStart(6)} ${String(numWarnings).padStart(8)} ${String(numInfos).padStart(5)}` +
        (numErrors || numWarnings ? '  FAIL' : ''),
    );
    for (const m of report.issues.messages) {
      if (m.severity <= 1)
        console.log(
          `    ${m.severity ? 'warning' : 'error'} ${m.code}: ${m.message} (${m.pointer ?? ''})`,
        );
    }
  }
}

// The levels-of-detail file of the default tree (`--lods`: nodes tree_LOD0..2), default and strict.
let lodFiles = 0;
if (only.length === 0 || only.includes('default')) {
  for (const [label, modeArgs] of [
    ['lods', []],
    ['lods strict', ['--strict']],
  ]) {
    const file = join(dir, `tree-${label.replace(/\W+/g, '-')}.glb`);
    execFileSync(sylva, ['generate', '--lods', ...modeArgs, '--out', file], { stdio: 'ignore' });
    const bytes = new Uint8Array(readFileSync(file));
    if (keepAt < 0) rmSync(file);
    const report = await validateBytes(bytes, { maxIssues: 100 });
    const { numErrors, numWarnings, numInfos } = report.issues;
    const extensions = extensionsOf(bytes);
    const bad = numErrors > 0 || numWarnings > 0 || (modeArgs.length > 0 && extensions.length > 0);
    if (bad) failed++;
    warnings += numWarnings;
    lodFiles++;
    console.log(
      `${'default'.padEnd(19)} ${label.padEnd(10)} ${mb(bytes.length)}  ${String(numErrors).padStart(6)} ${String(numWarnings).padStart(8)} ${String(numInfos).padStart(5)}` +
        (bad ? `  FAIL ${extensions.join(', ')}` : ''),
    );
    for (const m of report.issues.messages) {
      if (m.severity <= 1)
        console.log(`    ${m.severity ? 'warning' : 'error'} ${m.code}: ${m.message}`);
    }
  }
}

// The growth animation: the default tree (Age 40), a grown preset (grown_broadleaf, Age 35) and
// the default tree past its Mature Age (Age 60: its life played too, fewer leaves to keep it small).
let growthFiles = 0;
for (const [name, age, extra] of [
  ['default', 40, []],
  ['grown_broadleaf', 35, []],
  ['default', 60, ['--age', '60', '--set', 'leaves=6']],
]) {
  if (only.length > 0 && !only.includes(name)) continue;
  const file = join(dir, `${name}-${age}-growth.glb`);
  execFileSync(
    sylva,
    ['generate', '--preset', name, ...extra, '--growth-animation', '--out', file],
    { stdio: 'ignore' },
  );
  const bytes = new Uint8Array(readFileSync(file));
  if (keepAt < 0) rmSync(file);
  const report = await validateBytes(bytes, { maxIssues: 100 });
  const { numErrors, numWarnings, numInfos } = report.issues;
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const json = JSON.parse(
    new TextDecoder().decode(bytes.subarray(20, 20 + view.getUint32(12, true))),
  );
  const input = json.animations?.[0]?.samplers?.[0]?.input;
  const end = input === undefined ? undefined : json.accessors[input].max[0];
  const bad =
    numErrors > 0 || numWarnings > 0 || json.animations?.length !== 1 || Math.abs(end - age) > 1e-4;
  if (bad) failed++;
  warnings += numWarnings;
  growthFiles++;
  console.log(
    `${`${name}${extra.length > 0 ? ` at ${age}` : ''}`.padEnd(19)} ${'growth'.padEnd(10)} ${mb(bytes.length)}  ${String(numErrors).padStart(6)} ${String(numWarnings).padStart(8)} ${String(numInfos).padStart(5)}` +
      (bad ? `  FAIL (animation ends at ${end}, Age ${age})` : ''),
  );
  for (const m of report.issues.messages) {
    if (m.severity <= 1)
      console.log(`    ${m.severity ? 'warning' : 'error'} ${m.code}: ${m.message}`);
  }
}

// Native and wasm exporters write identical bytes (standing rule: same output on every target).
const glue = new URL('../packages/sylva-trees/src/wasm/sylva_wasm.js', import.meta.url);
if (existsSync(glue) && (only.length === 0 || only.includes('default'))) {
  const wasm = await import(glue);
  wasm.initSync({
    module: readFileSync(
      new URL('../packages/sylva-trees/src/wasm/sylva_wasm_bg.wasm', import.meta.url),
    ),
  });
  const oak = JSON.parse(wasm.presets_json()).find((p) => p.name === 'oak');
  for (const [label, input, cliArgs] of [
    ['default', {}, []],
    ['default + cut', { edits: [CUT] }, ['--edits', editsFile]],
    // Organ sets (acorns, cups, stalks): fruit 1 = Acorns.
    [
      'oak September acorns',
      { ...oak.values, fruit: 1, season: 9.5 },
      ['--preset', 'oak', '--set', 'fruit=1', '--set', 'season=9.5'],
    ],
  ]) {
    const tree = wasm.generate(JSON.stringify(input));
    if (typeof tree.to_glb !== 'function') {
      console.log('wasm parity: skipped (the wasm build predates to_glb; run scripts/setup.sh)');
    } else {
      for (const [leaves, modeArgs] of MODES) {
        const file = join(tmpdir(), `sylva-parity-${process.pid}.glb`);
        execFileSync(sylva, ['generate', ...cliArgs, ...modeArgs, '--out', file], {
          stdio: 'ignore',
        });
        const native = readFileSync(file);
        rmSync(file);
        const options = JSON.stringify(leaves === 'strict' ? { strict: true } : { leaves });
        const fromWasm = tree.to_glb(options);
        let same = Buffer.compare(native, Buffer.from(fromWasm)) === 0;
        // `to_glb_file` (the bytes read in place from the module's memory) writes the same file.
        if (typeof tree.to_glb_file === 'function') {
          const file = tree.to_glb_file(options);
          same &&=
            Buffer.compare(
              native,
              Buffer.from(file.memory().buffer, file.ptr(), file.byte_length()),
            ) === 0;
          file.free();
        }
        if (!same) failed++;
        console.log(
          `wasm parity (${label}, ${leaves}): ${same ? 'same bytes' : 'DIFFERENT BYTES'} (${fromWasm.length} bytes)`,
        );
      }
    }
    tree.free();
  }
  // The growth animation (`to_growth_glb_file`) is the CLI's `--growth-animation` file.
  const tree = wasm.generate('{}');
  if (typeof tree.to_growth_glb_file === 'function') {
    const file = join(tmpdir(), `sylva-parity-${process.pid}.glb`);
    execFileSync(sylva, ['generate', '--growth-animation', '--out', file], { stdio: 'ignore' });
    const native = readFileSync(file);
    rmSync(file);
    const glb = tree.to_growth_glb_file('{}', 40, 40);
    const same =
      Buffer.compare(native, Buffer.from(glb.memory().buffer, glb.ptr(), glb.byte_length())) === 0;
    glb.free();
    if (!same) failed++;
    console.log(
      `wasm parity (default, growth): ${same ? 'same bytes' : 'DIFFERENT BYTES'} (${native.length} bytes)`,
    );
  }
  tree.free();
}
if (keepAt < 0) rmSync(dir, { recursive: true, force: true });

console.log(
  `${trees.length * MODES.length + lodFiles + growthFiles} files, ${failed} failed, ${warnings} warnings`,
);
process.exit(failed ? 1 : 0);
