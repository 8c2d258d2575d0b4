/**
 * The `sylva-trees` package: a Vite library build (ES modules, `three` external) of the entries
 * that package.json `exports` names, `index.js` (the API), `core.js`, `url.js`, `viewer.js` and
 * `worker-client.js` (the subpaths `sylva-trees/core` … `sylva-trees/worker`) and `worker.js`
 * (the generator worker, `sylva-trees/worker-script`) and `helper.js` (the helper worker of the
 * threaded core), next to the core's `sylva_wasm_bg.wasm` and `sylva_wasm_threads_bg.wasm`.
 * All of them and their shared chunks sit in `dist/` itself, for the URLs below are written
 * relative to the module that holds them. Vite's library mode would inline the wasm (base64) and the worker (a
 * blob URL) and hide both behind expressions no other bundler can follow; instead the source's
 * `new URL('<source path>', import.meta.url)` of the worker and the wasm are written out as
 * `new URL('./worker.js', import.meta.url)` and `new URL('./sylva_wasm_bg.wasm', import.meta.url)`:
 * a browser resolves them next to the module (an import map, a CDN), and a consumer's bundler
 * (Vite, webpack 5, Rollup plugins) follows them and emits both files.
 *
 * The registry and the presets (`params`, `presets`) are read from the wasm module at build time
 * (`virtual:sylva-catalog`), so importing the package costs no wasm.
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import type { Plugin } from 'vite';
import { defineConfig } from 'vitest/config';

const here = (path: string): string => fileURLToPath(new URL(path, import.meta.url));
const WASM_DIR = here('./src/wasm');
const WASM_FILE = 'sylva_wasm_bg.wasm';
/** The core built with threads (worker/threads.ts), from src/wasm-threads. */
const THREADS_WASM_DIR = here('./src/wasm-threads');
const THREADS_WASM_FILE = 'sylva_wasm_threads_bg.wasm';

/** Source `new URL(...)` of a packaged file → the file's name in `dist/`. */
const PACKAGED_URLS: { module: RegExp; source: RegExp; file: string }[] = [
  {
    module: /src[\\/]runtime[\\/]startWorker\.ts$/,
    source: /new URL\('\.\.\/worker\/worker\.ts', import\.meta\.url\)/,
    file: './worker.js',
  },
  {
    module: /src[\\/]runtime[\\/]urls\.ts$/,
    source: /new URL\('\.\.\/wasm\/sylva_wasm_bg\.wasm', import\.meta\.url\)/,
    file: `./${WASM_FILE}`,
  },
  {
    module: /src[\\/]runtime[\\/]urls\.ts$/,
    source: /new URL\('\.\.\/wasm-threads\/sylva_wasm_bg\.wasm', import\.meta\.url\)/,
    file: `./${THREADS_WASM_FILE}`,
  },
  {
    module: /src[\\/]worker[\\/]threads\.ts$/,
    source: /new URL\('\.\/helper\.ts', import\.meta\.url\)/,
    file: './helper.js',
  },
  // The glues' own defaults (unused: the package always passes the module) must not be inlined.
  {
    module: /src[\\/]wasm[\\/]sylva_wasm\.js$/,
    source: /new URL\('sylva_wasm_bg\.wasm', import\.meta\.url\)/,
    file: `./${WASM_FILE}`,
  },
  {
    module: /src[\\/]wasm-threads[\\/]sylva_wasm\.js$/,
    source: /new URL\('sylva_wasm_bg\.wasm', import\.meta\.url\)/,
    file: `./${THREADS_WASM_FILE}`,
  },
];
const MARKER = /__SYLVA_PACKAGED_URL__\("([^"]+)"\)/g;

/** Writes the packaged files' URLs as plain `new URL(file, import.meta.url)` (see above). */
function packagedUrls(): Plugin {
  return {
    name: 'sylva:packaged-urls',
    apply: 'build',
    enforce: 'pre',
    transform(code, id) {
      let out = code;
      for (const url of PACKAGED_URLS) {
        if (!url.module.test(id)) continue;
        if (!url.source.test(out)) this.error(`${id} has no ${String(url.source)}`);
        out = out.replace(url.source, `__SYLVA_PACKAGED_URL__(${JSON.stringify(url.file)})`);
      }
      return out === code ? null : { code: out, map: null };
    },
    renderChunk(code) {
      if (!code.includes('__SYLVA_PACKAGED_URL__')) return null;
      return { code: code.replace(MARKER, "new URL('$1', import.meta.url)"), map: null };
    },
    generateBundle() {
      this.emitFile({
        type: 'asset',
        fileName: WASM_FILE,
        source: readFileSync(`${WASM_DIR}/${WASM_FILE}`),
      });
      this.emitFile({
        type: 'asset',
        fileName: THREADS_WASM_FILE,
        source: readFileSync(`${THREADS_WASM_DIR}/${WASM_FILE}`),
      });
    },
  };
}

/** `virtual:sylva-catalog`: the registry and presets JSON of the built core. */
function catalog(): Plugin {
  const id = 'virtual:sylva-catalog';
  return {
    name: 'sylva:catalog',
    resolveId: (source) => (source === id ? `\0${id}` : undefined),
    async load(resolved) {
      if (resolved !== `\0${id}`) return undefined;
      const glue = (await import(pathToFileURL(`${WASM_DIR}/sylva_wasm.js`).href)) as {
        initSync(options: { module: Uint8Array }): unknown;
        registry_json(): string;
        presets_json(): string;
        core_version(): string;
      };
      glue.initSync({ module: readFileSync(`${WASM_DIR}/${WASM_FILE}`) });
      return [
        `export const registryJson = ${JSON.stringify(glue.registry_json())};`,
        `export const presetsJson = ${JSON.stringify(glue.presets_json())};`,
        `export const coreVersion = ${JSON.stringify(glue.core_version())};`,
      ].join('\n');
    },
  };
}

export default defineConfig({
  plugins: [catalog(), packagedUrls()],
  build: {
    target: 'es2022',
    outDir: 'dist',
    emptyOutDir: true,
    sourcemap: false,
    minify: true,
    lib: {
      entry: {
        index: here('./src/index.ts'),
        core: here('./src/core/index.ts'),
        url: here('./src/url/index.ts'),
        viewer: here('./src/viewer/index.ts'),
        'worker-client': here('./src/worker/index.ts'),
        worker: here('./src/worker/worker.ts'),
        helper: here('./src/worker/helper.ts'),
      },
      formats: ['es'],
    },
    rolldownOptions: {
      external: [/^three($|\/)/],
      output: {
        entryFileNames: '[name].js',
        chunkFileNames: '[name]-[hash].js',
      },
    },
  },
  test: {
    include: ['src/**/*.test.ts'],
    environment: 'node',
    testTimeout: 30_000,
  },
});
