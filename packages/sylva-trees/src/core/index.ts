/**
 * `sylva-trees/core`: the parameter model, with neither three.js nor wasm. The wasm contract's
 * types (registry entries, presets, errors, mesh buffers and metadata), reading the registry and
 * presets from their JSON, parameter helpers (defaults, presets, snapping, grouping, the first
 * stage an edit reruns) and growth volumes. For apps that build their own controls around the
 * generator; the root entry `sylva-trees` needs none of it.
 */
export type * from './types';
export {
  applyPreset,
  defaultParams,
  displayValue,
  firstStage,
  groupParams,
  matchingPreset,
  normalizeValue,
  randomSeed,
  snapToStep,
} from './params';
export { parsePresets, parseRegistry } from './parse';
export { MAX_VOLUMES, newVolume, normalizeVolume } from './volumes';
