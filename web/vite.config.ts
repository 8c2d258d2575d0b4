/** Vite config: relative base so the static build works from any path, ES module workers. */
import react from '@vitejs/plugin-react';
import { randomBytes } from 'node:crypto';
import type { Plugin } from 'vite';
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

export default defineConfig({
  base: './',
  plugins: [react(), devCspNonce()],
  worker: { format: 'es' },
  build: {
    target: 'es2022',
    sourcemap: true,
    // three.js alone is ~600 kB minified; it gets its own long-cached chunk.
    chunkSizeWarningLimit: 800,
    rolldownOptions: {
      output: {
        codeSplitting: {
          groups: [
            { name: 'three', test: /node_modules[\\/]three[\\/]/ },
            { name: 'react', test: /node_modules[\\/](react|react-dom|scheduler)[\\/]/ },
          ],
        },
      },
    },
  },
  server: { port: 5173 },
  preview: { port: 4317, host: '127.0.0.1' },
  test: {
    include: ['src/**/*.test.ts'],
    environment: 'node',
    testTimeout: 30_000,
  },
});
