// Standing rule 5: the wasm build (run in Node) must give byte-identical buffers to the native
// build. Compares the content hash of every preset and a spread of seeds with `sylva generate`,
// for the single-threaded module and for the threaded one with a helper thread
// (scripts/wasm-threads-node.mjs), which must also have handed work to its helper.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { nativeCli } from './native-cli.mjs';
import { runThreaded, threadedModule } from './wasm-threads-node.mjs';

const wasm = await import(
  new URL('../packages/sylva-trees/src/wasm/sylva_wasm.js', import.meta.url)
);
wasm.initSync({
  module: readFileSync(
    new URL('../packages/sylva-trees/src/wasm/sylva_wasm_bg.wasm', import.meta.url),
  ),
});

const sylva = nativeCli();
const native = (args) =>
  JSON.parse(execFileSync(sylva, ['generate', ...args], { encoding: 'utf8' }));

const cases = [];
const presets = JSON.parse(wasm.presets_json());
for (const preset of presets) {
  cases.push({
    name: `preset ${preset.name}`,
    values: preset.values,
    args: ['--preset', preset.name],
  });
}
for (const seed of [0, 7, 123456, 4294967295]) {
  cases.push({ name: `seed ${seed}`, values: { seed }, args: ['--seed', String(seed)] });
}
// Seasons: a maple (umbrella) in mid-October (colours by light, leaves falling), an oak in its
// spring flush, and a fir's bronzed needles in January.
for (const [name, season] of [
  ['umbrella', 10.5],
  ['oak', 4.8],
  ['fir', 1.5],
]) {
  const preset = presets.find((p) => p.name === name);
  cases.push({
    name: `${name} season ${season}`,
    values: { ...preset.values, season },
    args: ['--preset', name, '--set', `season=${season}`],
  });
}
// Flowers and fruit: the oak bearing acorns (Fruit 1) in September (acorns, cups, stalks),
// the default tree in January (winter buds and the fallen leaves on the ground) and the quaking
// aspen's catkins in March: the hash covers the organ sets and the fallen leaves.
for (const [name, values] of [
  ['oak', { fruit: 1, season: 9.5 }],
  ['default', { season: 1.5 }],
  ['quaking_aspen', { season: 3.2 }],
]) {
  const preset = presets.find((p) => p.name === name);
  const set = Object.entries(values).flatMap(([k, v]) => ['--set', `${k}=${v}`]);
  cases.push({
    name: `${name} ${JSON.stringify(values)}`,
    values: { ...preset.values, ...values },
    args: ['--preset', name, ...set],
  });
}
// Age: the default tree at 10 of its 40 years, Black Tupelo at 30 of its 80, and Grown:
// Broadleaf at 12 of its 35 (the growth replay: birth years, the growth curve, young stems).
for (const [name, age] of [
  ['default', 10],
  ['black_tupelo', 30],
  ['grown_broadleaf', 12],
]) {
  const preset = presets.find((p) => p.name === name);
  cases.push({
    name: `${name} age ${age}`,
    values: { ...preset.values, age },
    args: ['--preset', name, '--set', `age=${age}`],
  });
}
// Life past the Mature Age (thickening, shedding into stubs with a callus, drooping) and Leafy
// Years: the default tree at 100 years, Black Tupelo at 130, and the default tree's leaves on
// the last 8 years of wood.
for (const [name, values] of [
  ['default', { age: 100 }],
  ['black_tupelo', { age: 130 }],
  ['default', { leaf_years: 8 }],
]) {
  const preset = presets.find((p) => p.name === name);
  const set = Object.entries(values).flatMap(([k, v]) => ['--set', `${k}=${v}`]);
  cases.push({
    name: `${name} ${JSON.stringify(values)}`,
    values: { ...preset.values, ...values },
    args: ['--preset', name, ...set],
  });
}
// Hand edits (a cut and a bend on two main branches of the default tree): the same edits give
// the same bytes natively (`--edits FILE`) and in wasm (the `edits` array of the parameters).
const edits = [
  { op: 'bend', at: [1.4077538, 5.961102, -1.6150186], to: [1.4077538, 6.461102, -1.3150186] },
  { op: 'cut', at: [-1.8003398, 5.9014244, 0.38097703] },
  { op: 'cut', at: [1.2, 7.5, 0.4], year: 38 },
  { op: 'cut', at: [30, 4, 0] },
];
const editsDir = mkdtempSync(join(tmpdir(), 'sylva-parity-'));
const stroke = Array.from({ length: 12 }, (_, i) => [3 + 0.25 * i, 9 + 0.05 * i, 0.1 * i]);
const paint = { op: 'paint', points: stroke, radius: 0.6, density: 400, segment: 0.25, kill: 0.4 };
const outline = [
  [0, 5],
  [5, 6],
  [0.5, 15],
  [0, 16],
];
// Paint on a Weber & Penn tree and on a grown one; a drawn crown (Crown Shape Drawn = 8) with a
// stroke and a cut after it.
const editCases = [
  ['edits', {}, edits],
  ['paint', {}, [paint]],
  ['paint grown_broadleaf', { preset: 'grown_broadleaf' }, [paint]],
  ['drawn crown', { shape: 8 }, [{ op: 'crown', outline }, paint, edits[1]]],
];
for (const [name, extra, list] of editCases) {
  const file = join(editsDir, `${name.replaceAll(' ', '_')}.json`);
  writeFileSync(file, JSON.stringify({ version: 1, edits: list }));
  const preset = extra.preset ? presets.find((p) => p.name === extra.preset) : null;
  const values = {
    ...(preset ? preset.values : {}),
    ...(extra.shape ? { shape: extra.shape } : {}),
    edits: list,
  };
  const args = ['--edits', file];
  if (preset) args.push('--preset', preset.name);
  if (extra.shape) args.push('--set', `shape=${extra.shape}`);
  cases.push({ name, values, args });
}
const threaded = await runThreaded(threadedModule(), {
  kind: 'generate',
  jsons: cases.map((c) => JSON.stringify(c.values)),
});
let passed = 0;
let failed = 0;
// The bounds the module reports (compared four floats at a time in wasm, `mesh/bounds.rs`)
// against a plain scan of its positions, with the same comparisons: `-0` and `0` told apart.
const scanBounds = (positions) => {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      const x = positions[i + k];
      if (x < min[k]) min[k] = x;
      if (x > max[k]) max[k] = x;
    }
  }
  return { min, max };
};
const sameBounds = (a, b) =>
  ['min', 'max'].every((e) => a[e].every((v, k) => Object.is(v, b[e][k])));
for (const [i, c] of cases.entries()) {
  const tree = wasm.generate(JSON.stringify(c.values));
  const meta = JSON.parse(tree.meta_json());
  const scanned = scanBounds(tree.positions());
  tree.free();
  const w = meta.hash;
  const n = native(c.args).hash;
  const t = threaded.metas[i].hash;
  const bounds = sameBounds(meta.bounds, scanned);
  if (w === n && t === n && bounds) {
    passed++;
    console.log(`ok   ${c.name}: ${w}`);
  } else {
    failed++;
    console.log(`FAIL ${c.name}: wasm ${w}, threaded wasm ${t}, native ${n}`);
    if (!bounds) {
      console.log(`     bounds ${JSON.stringify(meta.bounds)}, scanned ${JSON.stringify(scanned)}`);
    }
  }
}
// Every case needs the bark and the leaves: each hands its placement to the helper.
if (threaded.threads !== 2 || threaded.helperJobs < cases.length) {
  failed++;
  console.log(
    `FAIL the threaded module ran on ${threaded.threads} threads, its helper ${threaded.helperJobs} jobs for ${cases.length} trees`,
  );
}
console.log(
  `${passed} passed, ${failed} failed (threaded: its helper ran ${threaded.helperJobs} jobs)`,
);
process.exit(failed ? 1 : 0);
