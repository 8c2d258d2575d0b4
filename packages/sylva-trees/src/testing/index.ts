/**
 * `sylva-trees/testing`: test helpers for this repository's workspaces (the web app's Vitest),
 * the real wasm module read from `src/wasm` in Node, and the generator worker run in process
 * over it (`inProcessFactory`: the same messages a Web Worker sends, a task later). Resolved
 * from source only (the `sylva-source` condition): it is neither built nor published.
 */
export { realPresets, realRegistry } from './realWasm';
export { inProcessFactory } from '../runtime/inProcess';
