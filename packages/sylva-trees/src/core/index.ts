/**
 * `sylva-trees/core`: the parameter model, with neither three.js nor wasm. The wasm contract's
 * types (registry entries, presets, errors, mesh buffers and metadata), reading the registry and
 * presets from their JSON, parameter helpers (defaults, presets, snapping, grouping, the first
 * stage an edit reruns), growth volumes and the hand edit list (types, limits, strict JSON). For apps that build their own controls around the
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
export { mulberry32 } from './random';
export { MAX_VOLUMES, newVolume, normalizeVolume } from './volumes';
export {
  DEFAULT_BRUSH,
  DENSITY_RANGE,
  EDIT_OPS,
  EDITS_VERSION,
  EditsError,
  editsProblem,
  firstCrossing,
  GROUND,
  KILL_RANGE,
  MAX_COORD,
  MAX_EDIT_POINTS,
  MAX_EDITS,
  MAX_OUTLINE_POINTS,
  MAX_STROKE_POINTS,
  RADIUS_RANGE,
  SEGMENT_RANGE,
  summarizeEdit,
  validateEdits,
  type BendEdit,
  type CrownEdit,
  type CutEdit,
  type Edit,
  type EditPoint,
  type PaintEdit,
} from './edits';
export { editsDocument, parseEditsDocument, parseEditsValue } from './editsJson';
export { quantizeEdit, roundCm } from './editsQuantize';
