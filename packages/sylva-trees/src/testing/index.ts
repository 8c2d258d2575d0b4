/**
 * `sylva-trees/testing`: test helpers for this repository's workspaces (the web app's Vitest),
 * the real wasm module read from `src/wasm` in Node. Resolved from source only (the
 * `sylva-source` condition): it is neither built nor published.
 */
export { realPresets, realRegistry } from './realWasm';
