/** Test helper: instantiates the real wasm module synchronously in Node (vitest only). */
import { readFileSync } from 'node:fs';
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

/** The real parameter registry. */
export function realRegistry(): ParamSpec[] {
  return parseRegistry(loadWasm().registry_json());
}

/** The real presets. */
export function realPresets(): Preset[] {
  return parsePresets(loadWasm().presets_json());
}
