// `npm run bench [-- --json] [-- --runs N]`: median timings of every preset, native (the `sylva
// bench` CLI) and wasm (the release module in Node, the same build the browser runs).
// Reports per-stage medians, end-to-end medians (wasm: the JS call plus copying the buffers out,
// i.e. what the worker pays before posting), and output vertices per second.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { performance } from 'node:perf_hooks';

const args = process.argv.slice(2);
const asJson = args.includes('--json');
const runsArg = args.indexOf('--runs');
const runs = runsArg >= 0 ? Number(args[runsArg + 1]) : 30;
const root = fileURLToPath(new URL('..', import.meta.url));

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};

execFileSync('cargo', ['build', '--quiet', '--release', '-p', 'sylva-cli'], { cwd: root, stdio: 'inherit' });
const wasm = await import(new URL('../web/src/wasm/sylva_wasm.js', import.meta.url));
wasm.initSync({ module: readFileSync(new URL('../web/src/wasm/sylva_wasm_bg.wasm', import.meta.url)) });

const results = [];
for (const preset of JSON.parse(wasm.presets_json())) {
  const native = JSON.parse(
    execFileSync(`${root}/target/release/sylva`, ['bench', '--preset', preset.name, '--runs', String(runs), '--json'], {
      encoding: 'utf8',
    }),
  );
  const json = JSON.stringify(preset.values);
  const totals = [];
  const e2e = [];
  const stages = {};
  let meta;
  for (let i = 0; i < runs + 3; i++) {
    const t0 = performance.now();
    const tree = wasm.generate(json);
    const bufs = [tree.positions(), tree.normals(), tree.uvs(), tree.indices()];
    meta = JSON.parse(tree.meta_json());
    tree.free();
    const t1 = performance.now();
    if (i < 3 || bufs.length !== 4) continue; // warm-up
    totals.push(meta.total_ms);
    e2e.push(t1 - t0);
    for (const [k, v] of Object.entries(meta.stage_ms)) (stages[k] ??= []).push(v);
  }
  const stageMedian = Object.fromEntries(Object.entries(stages).map(([k, v]) => [k, median(v)]));
  const core = median(totals);
  const geometry = (stageMedian.skeleton ?? 0) + (stageMedian.mesh ?? 0);
  results.push({
    preset: preset.name,
    vertices: meta.vertices,
    triangles: meta.triangles,
    native: {
      median_ms: native.median_ms,
      stage_median_ms: native.stage_median_ms,
      vertices_per_second: native.vertices_per_second,
    },
    wasm: {
      median_ms: core,
      end_to_end_median_ms: median(e2e),
      stage_median_ms: stageMedian,
      vertices_per_second: meta.vertices / (core / 1000),
      skeleton_mesh_vertices_per_second: meta.vertices / (geometry / 1000),
    },
    same_hash: native.hash === meta.hash,
  });
}

if (asJson) {
  console.log(JSON.stringify({ runs, results }, null, 2));
} else {
  const f = (x) => x.toFixed(2).padStart(8);
  const mv = (x) => (x / 1e6).toFixed(1).padStart(7);
  console.log(`Medians over ${runs} runs (ms; M vertices/s). wasm e2e = generate + copy buffers out.`);
  console.log('preset            vertices  native ms  Mv/s  | wasm ms  skel   mesh   hash   e2e    Mv/s  geom Mv/s');
  for (const r of results) {
    const s = r.wasm.stage_median_ms;
    console.log(
      `${r.preset.padEnd(16)} ${String(r.vertices).padStart(9)} ${f(r.native.median_ms)} ${mv(r.native.vertices_per_second)} |` +
        `${f(r.wasm.median_ms)}${f(s.skeleton)}${f(s.mesh)}${f(s.hash)}${f(r.wasm.end_to_end_median_ms)}${mv(r.wasm.vertices_per_second)}${mv(r.wasm.skeleton_mesh_vertices_per_second)}` +
        (r.same_hash ? '' : '  HASH MISMATCH'),
    );
  }
}
