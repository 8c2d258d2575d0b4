/** Shared data types of the Sylva wasm contract (registry, presets, errors, mesh metadata). */

/** Kind of a generator parameter; every value is a number on the wire (bool 0/1, enum index). */
export type ParamKind = 'float' | 'int' | 'bool' | 'enum';

/** One entry of `registry_json()`: describes a generator parameter and its valid range. */
export interface ParamSpec {
  id: string;
  group: string;
  label: string;
  kind: ParamKind;
  default: number;
  min: number;
  max: number;
  step: number;
  unit: string;
  description: string;
  options?: string[];
}

/** One entry of `presets_json()`: only the non-default values are listed. */
export interface Preset {
  name: string;
  label: string;
  description: string;
  values: Record<string, number>;
}

/** Parameter values keyed by param id. */
export type Params = Record<string, number>;

/**
 * Error kinds the core reports (`panic` is also used for worker crashes; `timeout` is a
 * generation stopped by the scheduler's time limit).
 */
export type SylvaErrorKind =
  'invalid_param' | 'unknown_param' | 'budget' | 'panic' | 'timeout' | 'internal';

/** Structured error thrown (as JSON text) by `generate`, or synthesised by the worker pipeline. */
export interface SylvaError {
  kind: SylvaErrorKind;
  param?: string;
  message: string;
}

/** Material of an index range in the generated mesh. */
export type MaterialName = 'bark' | 'leaves';

/** An index range of the mesh drawn with one material. */
export interface MeshGroup {
  material: MaterialName;
  start: number;
  count: number;
}

/** Axis-aligned bounds in metres (Y up). */
export interface Bounds {
  min: [number, number, number];
  max: [number, number, number];
}

/** Parsed `meta_json()` of a generated tree. */
export interface TreeMeta {
  vertices: number;
  triangles: number;
  hash: string;
  bounds: Bounds;
  groups: MeshGroup[];
  stage_ms: Record<string, number>;
  total_ms: number;
  stems: number;
}

/** The mesh buffers of a generated tree plus its metadata. */
export interface TreeBuffers {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint32Array;
  /** Crown envelope preview as line segments (x, y, z per point, two points per segment). */
  envelope: Float32Array;
  meta: TreeMeta;
}

/** A `GeneratedTree` instance as exported by the wasm module. */
export interface WasmTree {
  positions(): Float32Array;
  normals(): Float32Array;
  uvs(): Float32Array;
  indices(): Uint32Array;
  envelope_lines(): Float32Array;
  meta_json(): string;
  free(): void;
}

/** The subset of the wasm module's exports the worker uses (after init). */
export interface WasmApi {
  registry_json(): string;
  presets_json(): string;
  core_version(): string;
  generate(paramsJson: string): WasmTree;
  take_panic(): string | undefined;
  debug_panic(): void;
}
