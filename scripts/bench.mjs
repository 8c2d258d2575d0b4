// `npm run bench [-- --json] [-- --runs N]`: median timings of every preset (and the named
// cases below), native (the `sylva bench` CLI) and wasm (the release module in Node, the same build the browser runs).
// Reports per-stage medians, end-to-end medians (wasm: the JS call plus copying the buffers out,
// i.e. what the worker pays before posting), and output vertices per second.
import { execFileSync } from 'node:child_process';
import { readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { fileURLToPath } from 'node:url';
import { performance } from 'node:perf_hooks';
import { benchBrowser } from './bench-browser.mjs';
import { benchBatch, benchCold, freshPageMicros } from './bench-cold.mjs';
import { median } from './bench-stats.mjs';
import { nativeCli } from './native-cli.mjs';

const args = process.argv.slice(2);
const asJson = args.includes('--json');
const runsArg = args.indexOf('--runs');
const runs = runsArg >= 0 ? Number(args[runsArg + 1]) : 30;
const root = fileURLToPath(new URL('..', import.meta.url));

const sylva = nativeCli();
const wasmGlue = new URL('../packages/sylva-trees/src/wasm/sylva_wasm.js', import.meta.url);
const wasmModule = new WebAssembly.Module(
  readFileSync(new URL('../packages/sylva-trees/src/wasm/sylva_wasm_bg.wasm', import.meta.url)),
);
const wasm = await import(wasmGlue);
wasm.initSync({ module: wasmModule });

// Every preset, plus the named cases the issues set targets for.
const cases = JSON.parse(wasm.presets_json()).map((p) => ({
  name: p.name,
  values: p.values,
  args: ['--preset', p.name],
}));
cases.push({
  name: 'grown_10k_markers',
  values: { growth_mode: 1, markers: 10000 },
  args: ['--set', 'growth_mode=1', '--set', 'markers=10000'],
});
// A 60-year grown tree (Grown: Broadleaf at Age 60, 25 years past its Mature Age: the growth
// replay and the life over decades) is computed in <= 1 s in wasm.
const broadleaf = JSON.parse(wasm.presets_json()).find((p) => p.name === 'grown_broadleaf');
if (broadleaf) {
  cases.push({
    name: 'grown_broadleaf_age60',
    values: { ...broadleaf.values, age: 60 },
    args: ['--preset', 'grown_broadleaf', '--set', 'age=60'],
  });
}
// Issue 4: the default tree with about 50,000 instanced leaves (34 per twig) regenerates in <= 30 ms.
cases.push({ name: 'leaves_50k', values: { leaves: 34 }, args: ['--set', 'leaves=34'] });

// V8 compiles the module's functions lazily and tiers the hot ones up in the background during
// its first trees; the first preset's runs caught that half done (the default tree's mesh stage
// at 8 to 22 ms in one run, 6 in the next): twenty trees first, their figures dropped.
for (let i = 0; i < 20; i++) wasm.generate('{}').free();

const results = [];
for (const preset of cases) {
  const native = JSON.parse(
    execFileSync(sylva, ['bench', ...preset.args, '--runs', String(runs), '--json'], {
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
    // The leaves the worker posts too (one mesh, per-instance matrices and colours).
    bufs.push(tree.leaf_matrices(), tree.leaf_colors(), tree.leaf_indices());
    meta = JSON.parse(tree.meta_json());
    tree.free();
    const t1 = performance.now();
    if (i < 3 || bufs.length !== 7) continue; // warm-up
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
    leaves: meta.leaves,
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

// The cold path of every preset (a whole generation with nothing kept from an earlier tree,
// native and wasm, 3 runs each) and a native batch of 100 default trees on every core
// (bench-cold.mjs).
const presetCases = cases.filter((c) => c.args[0] === '--preset');
const freshPageUs = await freshPageMicros();
const cold = await benchCold(sylva, wasmModule, wasmGlue.href, presetCases, 3, freshPageUs);
const batch = benchBatch(sylva, 100);

// Incremental regeneration (the worker's session), default tree in wasm: an edit of each stage,
// at full quality and as a drag is answered (a preview bark when the full one is over the
// worker's 4 ms budget), plus the copies out of the module and the hash that follows.
const incremental = {};
if (typeof wasm.Session === 'function') {
  const session = new wasm.Session();
  const edits = {
    skeleton: ['l1_length', 0.3, 0.01],
    mesh: ['mesh_quality', 1, 0.05],
    foliage: ['foliage_angle', 45, 1],
    leaf: ['leaf_teeth', 12, 1],
  };
  for (const [stage, [id, base, d]] of Object.entries(edits)) {
    const timed = (budget) => {
      session.update('{}', -1);
      const xs = [];
      let meta;
      for (let i = 0; i < runs + 3; i++) {
        const t0 = performance.now();
        meta = JSON.parse(
          session.update(JSON.stringify({ [id]: base + d * (1 + (i % 2)) }), budget),
        );
        if (i >= 3) xs.push(performance.now() - t0);
      }
      return { ms: median(xs), preview: meta.preview };
    };
    const full = timed(-1);
    const drag = timed(4);
    incremental[stage] = {
      param: id,
      full_ms: full.ms,
      drag_ms: drag.ms,
      drag_preview: drag.preview,
    };
  }
  const copy = [];
  const hash = [];
  for (let i = 0; i < runs; i++) {
    session.update(JSON.stringify({ seed: 1 + (i % 2) }), -1);
    let t0 = performance.now();
    for (const f of [
      'positions',
      'normals',
      'uvs',
      'indices',
      'wind',
      'leaf_matrices',
      'leaf_colors',
    ])
      session[f]();
    copy.push(performance.now() - t0);
    t0 = performance.now();
    session.hash();
    hash.push(performance.now() - t0);
  }
  incremental.copy_out_ms = median(copy);
  incremental.hash_ms = median(hash);
  session.free();
}

// The app in the browser: first tree, drags of the studio's sliders, a paint stroke and cuts
// (bench-browser.mjs, bench-edits.mjs).
execFileSync('npm', ['run', 'build', '-w', 'web'], { cwd: root, stdio: 'ignore' });
const browser = await benchBrowser(runs);
// With --json everything goes into this one object, printed at the end.
const report = { runs, results, fresh_page_us: freshPageUs, cold, batch, incremental, browser };

if (!asJson) {
  const inc = Object.entries(incremental).filter(([, v]) => typeof v === 'object');
  if (inc.length) {
    console.log(
      'Incremental edits of the default tree in wasm (median ms; drag = answer during a drag):\n' +
        inc
          .map(
            ([k, v]) =>
              `  ${k.padEnd(9)} (${v.param}): full ${v.full_ms.toFixed(2)}, drag ${v.drag_ms.toFixed(2)}${v.drag_preview ? ' (preview)' : ''}`,
          )
          .join('\n') +
        `\n  copy out ${incremental.copy_out_ms.toFixed(2)}, hash ${incremental.hash_ms.toFixed(2)}`,
    );
  }
  if (browser) {
    const d = browser.drag;
    console.log(
      `Browser (headless Chromium, built app, default tree): first tree in the scene ${browser.first_tree_in_scene_ms} ms after navigation, drawn ${browser.first_tree_ms} ms, with its shadows ${browser.first_shadowed_ms} ms.\n` +
        `Drag (${d.steps} steps, input to answer in the scene): median ${d.median_ms} ms, p95 ${d.p95_ms} ms; ` +
        `settle ${d.settle_ms} ms; next frame (upload + draw, SwiftShader) ${d.frame_ms} ms.\n` +
        `  per control: ${Object.entries(d.per_param)
          .map(([k, v]) => `${k} ${v}`)
          .join(', ')}`,
    );
    const { age, paint, cut } = browser;
    console.log(
      `Age (20-step drag toward younger trees): median ${age.median_ms} ms, p95 ${age.p95_ms} ms; settle ${age.settle_ms} ms.`,
    );
    console.log(
      `Paint (a ${paint.steps}-point stroke, per move, input to answer in the scene): median ${paint.median_ms} ms, p95 ${paint.p95_ms} ms; settle ${paint.settle_ms} ms.\n` +
        `Cut (${cut.cuts} clicks on main branches, release to answer): median ${cut.median_ms} ms, p95 ${cut.p95_ms} ms; settle ${cut.settle_ms} ms.`,
    );
  } else {
    console.log('Browser: skipped (no Chromium at /usr/bin/chromium or $SYLVA_CHROMIUM).');
  }
  const f = (x) => x.toFixed(2).padStart(8);
  const mv = (x) => (x / 1e6).toFixed(1).padStart(7);
  console.log(
    'Cold path (a whole generation, nothing kept from an earlier tree; medians of 3; µs per bark vertex, ms):\n' +
      'preset            vertices | native µs/v      ms | wasm µs/v      ms   memory MB  pages ms | 2 threads µs/v      ms  repeated ms',
  );
  for (const c of cold) {
    console.log(
      `${c.preset.padEnd(16)} ${String(c.vertices).padStart(9)} |${c.native.us_per_vertex.toFixed(3).padStart(11)}${c.native.median_ms.toFixed(1).padStart(8)} |` +
        `${c.wasm.us_per_vertex.toFixed(3).padStart(10)}${c.wasm.median_ms.toFixed(1).padStart(8)}` +
        `${c.wasm.memory_mb.toFixed(1).padStart(12)}${c.wasm.fresh_pages_ms.toFixed(1).padStart(10)} |` +
        `${c.wasm_threads.us_per_vertex.toFixed(3).padStart(15)}${c.wasm_threads.median_ms.toFixed(1).padStart(8)}` +
        `${c.wasm_threads.repeated.median_ms.toFixed(1).padStart(13)}` +
        (c.same_hash ? '' : '  HASH MISMATCH'),
    );
  }
  const floor = median(cold.map((c) => c.wasm.fresh_pages_us_per_vertex));
  console.log(
    `A fresh 4 KB page of wasm memory costs ${freshPageUs.toFixed(2)} µs here: faulting in a fresh instance's memory ` +
      `alone takes a median ${floor.toFixed(3)} µs per bark vertex over the presets ("pages ms").`,
  );
  console.log(
    `Batch: ${batch.trees} default trees (seeds 1-${batch.trees}) natively on ${batch.threads} threads: ` +
      `${batch.trees_per_second.toFixed(1)} trees/s (${batch.tree_median_ms.toFixed(1)} ms a tree)\n`,
  );
  console.log(
    `Medians over ${runs} runs (ms; M vertices/s). wasm e2e = generate + copy buffers out.`,
  );
  console.log(
    'preset            vertices  native ms  Mv/s  | wasm ms  skel   mesh   hash   e2e    Mv/s  geom Mv/s',
  );
  for (const r of results) {
    const s = r.wasm.stage_median_ms;
    console.log(
      `${r.preset.padEnd(16)} ${String(r.vertices).padStart(9)} ${f(r.native.median_ms)} ${mv(r.native.vertices_per_second)} |` +
        `${f(r.wasm.median_ms)}${f(s.skeleton)}${f(s.mesh)}${f(s.hash)}${f(r.wasm.end_to_end_median_ms)}${mv(r.wasm.vertices_per_second)}${mv(r.wasm.skeleton_mesh_vertices_per_second)}` +
        (r.same_hash ? '' : '  HASH MISMATCH'),
    );
  }
}

// GLB export (issue 7): the largest preset by vertices, native (`sylva bench --glb`: the first
// export encodes the PNG textures, later ones reuse them from the cache; the median is over the
// later ones, each into a fresh buffer, plus the medians into one reused buffer on every thread
// and on one; wasm has one) and wasm, in a
// fresh instance of the module so that its first export is a true first (PNG encoding, and the
// module's memory growing by the file's size): `to_glb_file` (the file written into the
// module's memory, read through a view: what the export worker does), the same plus a `Blob`
// of the view (what the worker hands to the download), and `to_glb` (the bytes copied out into
// a new Uint8Array). Budget: 100 ms.
if (typeof wasm.GeneratedTree?.prototype?.to_glb === 'function') {
  const largest = results.reduce((a, b) => (b.vertices > a.vertices ? b : a));
  const preset = cases.find((c) => c.name === largest.preset);
  const native = JSON.parse(
    execFileSync(sylva, ['bench', ...preset.args, '--glb', '--runs', String(runs), '--json'], {
      encoding: 'utf8',
    }),
  ).glb;
  const fresh = await import(
    new URL('../packages/sylva-trees/src/wasm/sylva_wasm.js?glb-bench', import.meta.url)
  );
  fresh.initSync({
    module: readFileSync(
      new URL('../packages/sylva-trees/src/wasm/sylva_wasm_bg.wasm', import.meta.url),
    ),
  });
  const tree = fresh.generate(JSON.stringify(preset.values));
  const timed = (f) => {
    const t0 = performance.now();
    const r = f();
    return [performance.now() - t0, r];
  };
  const series = { memory: [], blob: [], copy: [] };
  let bytes = 0;
  if (typeof tree.to_glb_file === 'function') {
    for (let i = 0; i <= runs; i++) {
      const t0 = performance.now();
      const file = tree.to_glb_file('');
      const view = new Uint8Array(file.memory().buffer, file.ptr(), file.byte_length());
      const t1 = performance.now();
      const blob = new Blob([view], { type: 'model/gltf-binary' });
      series.memory.push(t1 - t0);
      series.blob.push(performance.now() - t0);
      bytes = blob.size;
      file.free();
    }
  }
  for (let i = 0; i <= runs; i++) {
    const [ms, out] = timed(() => tree.to_glb(''));
    series.copy.push(ms);
    bytes = out.length;
  }
  tree.free();
  const summary = (xs) => (xs.length ? { median_ms: median(xs.slice(1)), first_ms: xs[0] } : null);
  const glb = {
    preset: preset.name,
    vertices: largest.vertices,
    bytes,
    budget_ms: 100,
    native,
    wasm: {
      runs,
      to_glb_file: summary(series.memory),
      to_glb_file_blob: summary(series.blob),
      // After to_glb_file's runs: no first export of its own.
      to_glb_copy: series.copy.length ? { median_ms: median(series.copy.slice(1)) } : null,
    },
  };
  report.glb = glb;
  if (!asJson) {
    const ms = (s) =>
      s
        ? `${s.median_ms.toFixed(1)} ms` +
          (s.first_ms === undefined ? '' : ` (${s.first_ms.toFixed(1)})`)
        : 'n/a';
    console.log(
      `\nGLB export, ${glb.preset} (${glb.vertices} vertices, ${(bytes / 1e6).toFixed(1)} MB), median of ${runs} ` +
        `(first export in brackets; budget 100 ms):\n` +
        `  native: ${native.median_ms.toFixed(1)} ms (${native.first_ms.toFixed(1)}) into a fresh buffer, ` +
        `${native.reused_buffer_median_ms.toFixed(1)} ms into a reused one (${native.threads} threads; ` +
        `${native.reused_buffer_one_thread_median_ms.toFixed(1)} ms on one)\n` +
        `  wasm: ${ms(glb.wasm.to_glb_file)} into the module's memory, ${ms(glb.wasm.to_glb_file_blob)} to a Blob, ` +
        `${ms(glb.wasm.to_glb_copy)} copied out by to_glb`,
    );
  }
}

// Leaves (issue 4): a full leaf with 5,000 auxin sources, Open venation (Oak, budget 5 ms) and
// Closed (Maple, budget 10 ms), native (`sylva bench-leaf`, the same parameters) and wasm
// (`leaf_json`; core = the module's own stage clock, e2e = the call including the JSON). With
// --json the leaf report is a second JSON object on its own line.
if (typeof wasm.leaf_json === 'function') {
  const leafNative = JSON.parse(
    execFileSync(sylva, ['bench-leaf', '--runs', String(runs), '--json'], { encoding: 'utf8' }),
  );
  const leafResults = [];
  for (const r of leafNative.results) {
    const json = JSON.stringify(r.params);
    const core = [];
    const e2e = [];
    const stages = {};
    let leaf;
    for (let i = 0; i < runs + 3; i++) {
      const t0 = performance.now();
      const out = wasm.leaf_json(json);
      const t1 = performance.now();
      if (i === runs + 2) leaf = JSON.parse(out);
      if (i < 3) continue; // warm-up
      // Only the timings are read back each run (parsing the whole leaf would feed the GC).
      const ms = JSON.parse(
        out.slice(out.lastIndexOf('"ms":{') + 5, out.lastIndexOf(',"total_ms"')),
      );
      core.push(Number(out.slice(out.lastIndexOf('"total_ms":') + 11, -1)));
      e2e.push(t1 - t0);
      for (const [k, v] of Object.entries(ms)) (stages[k] ??= []).push(v);
    }
    leafResults.push({
      preset: r.preset,
      venation: r.venation,
      auxins: leaf.auxins.length - 1,
      vein_nodes: leaf.veins.nodes.length,
      loops: leaf.loops,
      budget_wasm_ms: r.venation === 'Closed' ? 10 : 5,
      native: { median_ms: r.median_ms, stage_median_ms: r.stage_median_ms },
      wasm: {
        median_ms: median(core),
        end_to_end_median_ms: median(e2e),
        stage_median_ms: Object.fromEntries(Object.entries(stages).map(([k, v]) => [k, median(v)])),
      },
      same_hash: r.hash === leaf.hash,
    });
  }
  report.leaf = { runs, results: leafResults };
  if (!asJson) {
    const f = (x) => x.toFixed(2).padStart(8);
    console.log(
      `\nLeaves, 5,000 auxin sources, medians over ${runs} runs (ms). wasm e2e = leaf_json including JSON.`,
    );
    console.log(
      'leaf     venation  nodes loops | native ms  veins |  wasm ms  veins  budget    e2e',
    );
    for (const r of leafResults) {
      const within = r.wasm.median_ms <= r.budget_wasm_ms ? 'ok' : 'OVER';
      console.log(
        `${r.preset.padEnd(8)} ${r.venation.padEnd(8)} ${String(r.vein_nodes).padStart(6)} ${String(r.loops).padStart(5)} |` +
          `${f(r.native.median_ms)}${f(r.native.stage_median_ms.veins)} |${f(r.wasm.median_ms)}${f(r.wasm.stage_median_ms.veins)}` +
          ` ${String(r.budget_wasm_ms).padStart(3)} ${within.padEnd(4)}${f(r.wasm.end_to_end_median_ms)}` +
          (r.same_hash ? '' : '  HASH MISMATCH'),
      );
    }
  }
}

// Forest (issue 7): the instancing data of a 10,000-tree forest (seeded scatter, per-(variety,
// LOD) buckets and the LOD assignment), the plain TS module the forest view runs, timed by
// Vitest's bench (tinybench) in Node. Budget: 200 ms.
{
  const out = `${tmpdir()}/sylva-forest-bench-${process.pid}.json`;
  execFileSync(
    'npx',
    ['vitest', 'bench', '--run', 'src/forest/layout.bench.ts', '--outputJson', out],
    {
      cwd: `${root}/web`,
      stdio: 'ignore',
    },
  );
  const vitest = JSON.parse(readFileSync(out, 'utf8'));
  rmSync(out, { force: true });
  const forest = vitest.files
    .flatMap((f) => f.groups)
    .flatMap((g) => g.benchmarks)
    .map((b) => ({ name: b.name, median_ms: b.median, samples: b.sampleCount }));
  report.forest = { trees: 10_000, budget_ms: 200, results: forest };
  if (!asJson) {
    console.log('\nForest instancing data, 10,000 trees (Node, medians; budget 200 ms):');
    for (const r of forest)
      console.log(
        `  ${r.name.padEnd(46)} ${r.median_ms.toFixed(2).padStart(8)} ms  (${r.samples} samples)`,
      );
  }
}

if (asJson) console.log(JSON.stringify(report, null, 2));
