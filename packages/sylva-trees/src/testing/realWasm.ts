/** Test helper: instantiates the real wasm module synchronously in Node (vitest only). */
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import * as wasm from '../wasm/sylva_wasm.js';
import { parsePresets, parseRegistry } from '../core/parse';
import type { ParamSpec, Preset, WasmApi } from '../core/types';

let initialised = false;

/** The wasm API, initialised once per test file from `src/wasm/sylva_wasm_bg.wasm`. */
export function loadWasm(): WasmApi {
  if (!initialised) {
    const path = fileURLToPath(new URL('../wasm/sylva_wasm_bg.wasm', import.meta.url));
    wasm.initSync({ module: readFileSync(path) });
    initialised = true;
  }
  return wasm;
}

/**
 * The core built with the `debug-hooks` feature (`debug_panic`, `debug_near_x`), from `src/wasm-debug`, which
 * `scripts/setup.sh --test` builds (one instance: after a panic it is unusable).
 */
export async function loadDebugWasm(): Promise<WasmApi> {
  const dir = new URL('../wasm-debug/', import.meta.url);
  const module = fileURLToPath(new URL('sylva_wasm_bg.wasm', dir));
  if (!existsSync(module)) {
    throw new Error(`${module} is missing: run \`bash scripts/setup.sh --test\` (the debug core)`);
  }
  // A path the type checker does not follow: the folder exists only after `setup.sh --test`.
  const glue = (await import(/* @vite-ignore */ new URL('sylva_wasm.js', dir).href)) as WasmApi & {
    initSync(options: { module: Uint8Array }): unknown;
  };
  glue.initSync({ module: readFileSync(module) });
  return glue;
}

/** The real parameter registry. */
export function realRegistry(): ParamSpec[] {
  return parseRegistry(loadWasm().registry_json());
}

/** The real presets. */
export function realPresets(): Preset[] {
  return parsePresets(loadWasm().presets_json());
}
