/**
 * Where the wasm module is: next to this module, written as `new URL('…', import.meta.url)` so
 * that every bundler follows it (the app's Vite build emits it), a browser resolves it from any
 * host and path, and the package build rewrites the source path to the file in `dist/`
 * (vite.config.ts, `packagedUrls`).
 */

/** The core's wasm file. */
export function wasmUrl(): URL {
  return new URL('../wasm/sylva_wasm_bg.wasm', import.meta.url);
}

/** The core's wasm file built with threads (`worker/threads.ts`). */
export function threadsWasmUrl(): URL {
  return new URL('../wasm-threads/sylva_wasm_bg.wasm', import.meta.url);
}
