/**
 * Vite config: relative base so the static build works from any path, ES module workers, and a
 * multi-page build: the app (index.html), the embed page, the docs page, and `sylva-tree.js`
 * (the `<sylva-tree>` element) under a stable, unhashed name for other sites to load.
 */
import react from '@vitejs/plugin-react';
import { randomBytes } from 'node:crypto';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { defaultClientConditions, defaultServerConditions, type Plugin } from 'vite';
import { defineConfig } from 'vitest/config';
import { withNonce } from './src/security/csp.ts';

/**
 * Dev server only: the CSP in index.html allows no inline code, but Vite's dev client injects
 * `<style>` tags and React Refresh an inline preamble. A nonce made per server start is added
 * to the policy and (through `html.cspNonce`) to those tags. The build is left untouched.
 */
function devCspNonce(): Plugin {
  const nonce = randomBytes(18).toString('base64');
  return {
    name: 'sylva:dev-csp-nonce',
    apply: 'serve',
    config: () => ({ html: { cspNonce: nonce } }),
    transformIndexHtml: { order: 'pre', handler: (html) => withNonce(html, nonce) },
  };
}

/** Entry name of the custom element script, emitted as `sylva-tree.js` at the site root. */
const ELEMENT_ENTRY = 'sylva-tree';
const ELEMENT_SOURCE = '/src/element/sylva-tree.ts';

/** Dev server only: serves `/sylva-tree.js` (as used by public/element-demo.html) from source. */
function devElementScript(): Plugin {
  return {
    name: 'sylva:dev-element-script',
    apply: 'serve',
    configureServer(server) {
      server.middlewares.use((req, _res, next) => {
        if (req.url?.split('?')[0]?.endsWith(`/${ELEMENT_ENTRY}.js`)) req.url = ELEMENT_SOURCE;
        next();
      });
    },
  };
}

/** The sylva-trees package's sources. */
const PACKAGE_SRC = fileURLToPath(new URL('../packages/sylva-trees/src/', import.meta.url));

/**
 * `vite build --mode debug` (`npm run build:debug`, into web/dist-debug) only: the app whose
 * generator worker carries the test hooks, for the e2e tests of the crash recovery and the time
 * limit. The worker's `./debugHooks` becomes `debug.ts` (the hooks) and the core becomes its
 * `debug-hooks` build (`debug_panic`, in packages/sylva-trees/src/wasm-debug, which
 * `scripts/setup.sh --test` builds). web/dist, the shipped app, has neither.
 */
function debugBuild(): Plugin {
  let active = false;
  const debugWasm = `${PACKAGE_SRC}wasm-debug/`;
  return {
    name: 'sylva:debug-build',
    enforce: 'pre',
    configResolved(config) {
      active = config.mode === 'debug';
    },
    buildStart() {
      if (active && !existsSync(`${debugWasm}sylva_wasm_bg.wasm`)) {
        this.error(`${debugWasm} is missing: run \`bash scripts/setup.sh --test\` first`);
      }
    },
    resolveId(source, importer) {
      if (!active || !importer) return null;
      if (source === './debugHooks' && /worker[\\/]worker\.ts$/.test(importer)) {
        return `${PACKAGE_SRC}worker/debug.ts`;
      }
      if (source === '../wasm/sylva_wasm.js') return `${debugWasm}sylva_wasm.js`;
      if (source === '../wasm-threads/sylva_wasm.js') {
        return `${PACKAGE_SRC}wasm-threads-debug/sylva_wasm.js`;
      }
      return null;
    },
    transform(code, id) {
      if (!active || !/runtime[\\/]urls\.ts$/.test(id)) return null;
      const wasm = "'../wasm/sylva_wasm_bg.wasm'";
      const threads = "'../wasm-threads/sylva_wasm_bg.wasm'";
      if (!code.includes(wasm)) this.error(`${id} has no ${wasm}`);
      if (!code.includes(threads)) this.error(`${id} has no ${threads}`);
      const out = code
        .replace(wasm, "'../wasm-debug/sylva_wasm_bg.wasm'")
        .replace(threads, "'../wasm-threads-debug/sylva_wasm_bg.wasm'");
      return { code: out, map: null };
    },
  };
}

/**
 * Cross-origin isolation for the dev server and `vite preview`: with these two headers a page may
 * share memory with its workers, so the generator worker runs the core built with threads and a
 * helper worker (docs/hosting.md; a static host without them gets the single-threaded core).
 * Every resource the app loads is its own, so `require-corp` blocks nothing.
 */
const ISOLATION_HEADERS = {
  'Cross-Origin-Opener-Policy': 'same-origin',
  'Cross-Origin-Embedder-Policy': 'require-corp',
};

const page = (path: string): string => fileURLToPath(new URL(path, import.meta.url));

/**
 * The `sylva-trees` package's entries (its package.json `exports`) resolve to its TypeScript
 * sources under this condition, so the app, its workers and its tests build from source; a
 * published package resolves to its built `dist/` files instead.
 */
const SOURCE_CONDITION = 'sylva-source';

export default defineConfig({
  base: './',
  plugins: [react(), devCspNonce(), devElementScript(), debugBuild()],
  resolve: { conditions: [SOURCE_CONDITION, ...defaultClientConditions] },
  ssr: { resolve: { conditions: [SOURCE_CONDITION, ...defaultServerConditions] } },
  // The worker bundle has plugins of its own: the debug build redirects inside it too.
  worker: { format: 'es', plugins: () => [debugBuild()] },
  build: {
    target: 'es2022',
    sourcemap: true,
    // three.js alone is ~600 kB minified; it gets its own long-cached chunk.
    chunkSizeWarningLimit: 800,
    rolldownOptions: {
      input: {
        index: page('./index.html'),
        embed: page('./embed.html'),
        docs: page('./docs.html'),
        [ELEMENT_ENTRY]: page(`.${ELEMENT_SOURCE}`),
      },
      output: {
        // Pages load hashed entry chunks; other sites load the element by a stable URL.
        entryFileNames: (chunk) =>
          chunk.name === ELEMENT_ENTRY ? `${ELEMENT_ENTRY}.js` : 'assets/[name]-[hash].js',
        codeSplitting: {
          groups: [
            { name: 'three', test: /node_modules[\\/]three[\\/]/ },
            { name: 'react', test: /node_modules[\\/](react|react-dom|scheduler)[\\/]/ },
          ],
        },
      },
    },
  },
  server: { port: 5173, headers: ISOLATION_HEADERS },
  preview: { port: 4317, host: '127.0.0.1', headers: ISOLATION_HEADERS },
  test: {
    include: ['src/**/*.test.ts'],
    environment: 'node',
    testTimeout: 30_000,
  },
});
