/** Shared data types of the Sylva wasm contract (registry, presets, errors, mesh metadata). */
import type { LeafPresetId, ParamId, PresetId } from './generated/params';
import type {
  CoreError,
  CoreErrorKind,
  BarkStyle,
  Stage,
  TreeMeta as CoreTreeMeta,
} from './generated/payloads';

// Generated from the core's registry and presets (`npm run docs`, `sylva params --typescript`).
export type {
  EnumParamId,
  LeafPresetId,
  ParamId,
  ParamOptions,
  PresetId,
  PresetValues,
} from './generated/params';

// Generated from the core's payload structs (`npm run docs`, `sylva params --payloads`).
export type {
  BarkStyle,
  Bounds,
  CoreError,
  CoreErrorKind,
  EditReport,
  LeafInspection,
  LodLevelMeta,
  LodMeta,
  MaterialName,
  MeshGroup,
  Stage,
  TreeChanges,
} from './generated/payloads';

/** Kind of a generator parameter; every value is a number on the wire (bool 0/1, enum index). */
export type ParamKind = 'float' | 'int' | 'bool' | 'enum';

/** One entry of `registry_json()`: describes a generator parameter and its valid range. */
export interface ParamSpec {
  id: ParamId;
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
  /** The first stage the parameter affects (absent in hand-made specs: `skeleton`). */
  stage?: Stage;
}

/**
 * One entry of `presets_json()` (a tree preset) or `leaf_presets_json()` (a leaf preset, with
 * `Name` = `LeafPresetId`): only the non-default values are listed.
 */
export interface Preset<Name extends string = PresetId> {
  name: Name;
  label: string;
  description: string;
  values: Params;
}

/** A leaf preset (`leaf_presets_json()`). */
export type LeafPreset = Preset<LeafPresetId>;

/** Parameter values keyed by param id (a full set, or some of them). */
export type Params = Partial<Record<ParamId, number>>;

/**
 * Error kinds: the core's (`CoreErrorKind`), plus `panic` (also used for worker crashes),
 * `timeout` (a generation stopped by the scheduler's time limit) and `internal` (anything else
 * the worker pipeline caught).
 */
export type SylvaErrorKind = CoreErrorKind | 'panic' | 'timeout' | 'internal';

/** Structured error thrown (as JSON text) by `generate`, or synthesised by the worker pipeline. */
export interface SylvaError extends Omit<CoreError, 'kind'> {
  kind: SylvaErrorKind;
}

/**
 * A tree's parsed meta (the core's `TreeMeta`), its `hash` always a string: a session update
 * has none, so it is '' while it is computed, and for a preview.
 */
export interface TreeMeta extends CoreTreeMeta {
  hash: string;
}

/** The leaf texture (RGBA8, row 0 = v 0), sent only when the leaf shape changed. */
export interface LeafTextureBuffers {
  width: number;
  height: number;
  rgba: Uint8Array;
}

/** The leaves of a tree: one leaf mesh (leaf units) drawn once per instance. */
export interface FoliageBuffers {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint32Array;
  /** Column-major 4x4 matrix per leaf (16 floats). */
  matrices: Float32Array;
  /** RGB tint per leaf (3 floats). */
  colors: Float32Array;
  /** The baked texture, or null when it is the same as the previous tree's. */
  texture: LeafTextureBuffers | null;
  /** `meta.leaf_hash`: which leaf shape the mesh and texture are. */
  leafHash: string;
}

/** What an organ set is (`sylva_core::organs::OrganKind`). */
export type OrganKind =
  'petals' | 'flower_centre' | 'catkin' | 'bud' | 'fruit' | 'fruit_part' | 'stalk';

/**
 * One kind of flower, fruit, catkin or bud (`sylva_core::organs::OrganSet`, the wasm's
 * `organs_json` and `organ_*` getters): `positions`/`normals`/`indices` drawn once per instance,
 * double-sided, in a plain material of `color` and `roughness`.
 */
export interface OrganSetBuffers {
  kind: OrganKind;
  /** A name for objects and materials (`"acorns"`, `"cherry blossom petals"`). */
  name: string;
  /** Base colour, sRGB 0..1. */
  color: [number, number, number];
  roughness: number;
  /** The part in metres (x, y, z per vertex; attachment at the origin, along +y). */
  positions: Float32Array;
  /** Unit normal per vertex. */
  normals: Float32Array;
  /** Triangle list. */
  indices: Uint32Array;
  /** Column-major 4x4 matrix per instance (16 floats). */
  matrices: Float32Array;
  /** RGB tint per instance (3 floats, linear light, multiplies `color`). */
  colors: Float32Array;
}

/** The bark arrays of a tree (see `TreeMesh`). */
export interface BarkBuffers {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint32Array;
  /** Wind data, 8 floats per vertex, or empty. */
  wind: Float32Array;
  /** Boxes of runs of triangles for picking (`core/pickBoxes.ts`); absent: pick every triangle. */
  pick?: Float32Array;
}

/** The leaf mesh drawn once per leaf (leaf units). */
export interface LeafMeshBuffers {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint32Array;
}

/**
 * What one answer of the worker's session carries: the meta, and only the arrays that changed
 * since its previous answer (absent = keep what you have).
 */
export interface TreeUpdate {
  meta: TreeMeta;
  bark?: BarkBuffers;
  /** Crown envelope line segments (with a new skeleton). */
  envelope?: Float32Array;
  /** Growth markers (with a new skeleton). */
  markers?: Float32Array;
  /** Per-leaf matrices and tints. */
  instances?: { matrices: Float32Array; colors: Float32Array };
  /** The flowers, fruit, catkins and buds (sent with the placements; [] = none). */
  organs?: OrganSetBuffers[];
  /**
   * The mean tint of the leaves on the tree (linear light; the fallen ones left out), sent with
   * the placements: the Season's leaf colour for the leaf inspector. Null: no leaf on the tree.
   */
  leafTint?: [number, number, number] | null;
  leafMesh?: LeafMeshBuffers;
  /** The leaf texture (a new leaf shape). */
  leafTexture?: LeafTextureBuffers;
  /** The baked bark maps (a worker's first answer, and when the bark type changes). */
  barkTextures?: BarkTextureBuffers;
  /**
   * The end grain of the cut faces (the first answer with a `cut_face` group, and when the bark
   * type of a tree with one changes).
   */
  endGrain?: EndGrainBuffers;
  /** Bark occlusion, one byte per vertex (with a new bark or new leaves; empty: a preview). */
  shade?: Uint8Array;
}

/** The mesh buffers of a generated tree plus its metadata. */
export interface TreeBuffers {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint32Array;
  /** Crown envelope preview as line segments (x, y, z per point, two points per segment). */
  envelope: Float32Array;
  /** Growth mode: the markers sampled in the crown (x, y, z each; empty otherwise). */
  markers?: Float32Array;
  meta: TreeMeta;
  /** The leaves (absent from hand-made test buffers). */
  foliage?: FoliageBuffers;
  /** Flowers, fruit, catkins and buds, one set per kind (absent or [] = none). */
  organs?: OrganSetBuffers[];
  /** Mean tint of the leaves on the tree (see `TreeUpdate.leafTint`); absent or null: none. */
  leafTint?: [number, number, number] | null;
  /**
   * Wind data, 8 floats per vertex (`pivot xyz, level, phase, stiffness, distance, radius`, see
   * `TreeMesh.wind`); absent or empty when the core has none (the viewer falls back).
   */
  wind?: Float32Array;
  /** The baked bark textures, sent with a worker's first result and when the bark type changes. */
  bark?: BarkTextureBuffers;
  /** The end grain of cut faces, once a tree with a cut arrived. */
  endGrain?: EndGrainBuffers;
  /** Bark occlusion, one byte per vertex (0 dark .. 255 open sky; `TreeMesh.shade`); may be empty. */
  shade?: Uint8Array;
  /** Boxes of runs of bark triangles for picking (`core/pickBoxes.ts`); absent: none. */
  pick?: Float32Array;
}

/** The core's procedural bark maps (`bark_maps`): RGBA8, `size`², row 0 = v 0. */
export interface BarkTextureBuffers {
  size: number;
  /** The `bark_type` index these maps are. */
  kind: number;
  /** Colour (sRGB). */
  color: Uint8Array;
  /** Tangent-space normal (RGB = xyz·0.5 + 0.5) and height (A). */
  normal: Uint8Array;
  /** Occlusion (R), roughness (G), metalness (B). */
  orm: Uint8Array;
  style: BarkStyle;
}

/**
 * The core's end grain for the faces of cut stems (`end_grain_maps`, layout in the core's
 * `EndGrainMaps::to_bytes`): RGBA8, `size`², row 0 = v 0, drawn as a disc in the faces' disc
 * uvs (pith at 0.5, 0.5).
 */
export interface EndGrainBuffers {
  size: number;
  /** The `bark_type` index this wood is. */
  kind: number;
  /** Colour (sRGB), alpha = the disc mask. */
  color: Uint8Array;
  /** Tangent-space normal (RGB = xyz·0.5 + 0.5) and height (A). */
  normal: Uint8Array;
}

/** Shape of a user volume primitive (growth mode). */
export type VolumeKind = 'sphere' | 'box' | 'cylinder';
/** What a volume primitive does: holds markers, holds none, or also stops branches. */
export type VolumeGroup = 'crown' | 'shadow' | 'exclusion';

/**
 * A user volume primitive as the app keeps it. `size` is `[radius, radius, radius]` for a
 * sphere, `[width, height, depth]` for a box and `[radius, height, radius]` for a cylinder
 * (metres); `volumeToCore` gives the core's JSON form.
 */
export interface VolumePrimitive {
  kind: VolumeKind;
  group: VolumeGroup;
  centre: [number, number, number];
  size: [number, number, number];
}

/** A `GeneratedTree` instance as exported by the wasm module. */
export interface WasmTree {
  positions(): Float32Array;
  normals(): Float32Array;
  uvs(): Float32Array;
  indices(): Uint32Array;
  /**
   * Wind attributes, 8 floats per bark vertex: pivot x, y, z (the stem's base), level, phase
   * (0..1 per stem), stiffness (0..1), distance from the root (m), local radius (m). Optional so
   * older fakes still type-check.
   */
  wind?(): Float32Array;
  envelope_lines(): Float32Array;
  /** Growth mode: the markers (x, y, z each); optional so older fakes still type-check. */
  markers?(): Float32Array;
  meta_json(): string;
  /** Foliage (optional so that test fakes may leave them out). */
  leaf_positions?(): Float32Array;
  leaf_normals?(): Float32Array;
  leaf_uvs?(): Float32Array;
  leaf_indices?(): Uint32Array;
  leaf_matrices?(): Float32Array;
  leaf_colors?(): Float32Array;
  leaf_texture?(): Uint8Array;
  /** Bark occlusion (one byte per vertex); optional: test fakes lack it. */
  shade?(): Uint8Array;
  /** Wind data (8 floats per vertex); optional: older cores and test fakes lack it. */
  wind?(): Float32Array;
  /**
   * Exporters (optional so that test fakes may leave them out). `optionsJson` is a JSON object of
   * `ExportOptions` fields (`leaves`: 'instanced' | 'baked' | 'none', `wind`, `textures`,
   * `normal_maps`, `vertex_colors`, `bark_texture_size`); '' takes the defaults. Bad options throw
   * a JSON `SylvaError` string.
   */
  to_glb?(optionsJson: string): Uint8Array;
  /** Wavefront OBJ text; `name` is the file stem it refers to (`mtllib name.mtl`). */
  to_obj?(name: string, optionsJson: string): string;
  /** The MTL text for `to_obj` (textures `name_bark_color.png`, ...). */
  to_mtl?(name: string, optionsJson: string): string;
  /** File names of the PNG textures the MTL refers to, in `obj_texture` index order. */
  obj_texture_names?(name: string, optionsJson: string): string[];
  /** PNG file `index` of `obj_texture_names` (rows flipped for OBJ's bottom-up UVs). */
  obj_texture?(optionsJson: string, index: number): Uint8Array;
  free(): void;
}

/** A `Session` of the wasm module: incremental generation (see `sylva_core::session`). */
export interface WasmSession {
  /** Meta JSON with `changes` and `preview`; budget >= 0 allows a preview bark. */
  update(
    paramsJson: string,
    previewBudgetMs: number,
    progress?: (fraction: number) => void,
  ): string;
  /** Hash of the current full tree; undefined for a preview. */
  hash(): string | undefined;
  clear(): void;
  positions(): Float32Array;
  normals(): Float32Array;
  uvs(): Float32Array;
  indices(): Uint32Array;
  wind(): Float32Array;
  markers(): Float32Array;
  envelope_lines(): Float32Array;
  leaf_positions(): Float32Array;
  leaf_normals(): Float32Array;
  leaf_uvs(): Float32Array;
  leaf_indices(): Uint32Array;
  leaf_matrices(): Float32Array;
  leaf_colors(): Float32Array;
  leaf_texture(): Uint8Array;
  /** Bark occlusion, one byte per vertex (empty for a preview). */
  shade(): Uint8Array;
  /**
   * The bark's pick boxes (`pickBoxes`' layout), computed in the core (optional: test fakes and
   * older builds lack it, and the worker computes them itself).
   */
  pick_boxes?(): Float32Array;
  /**
   * The organ sets (optional: test fakes and older builds lack them): their count, then
   * `[{kind, name, color, roughness, count}]` as JSON and set `i`'s arrays.
   */
  organ_count?(): number;
  organs_json?(): string;
  organ_positions?(i: number): Float32Array;
  organ_normals?(i: number): Float32Array;
  organ_indices?(i: number): Uint32Array;
  organ_matrices?(i: number): Float32Array;
  organ_colors?(i: number): Float32Array;
  /** How many leaf instances, the last ones, lie on the ground (optional: fakes lack it). */
  fallen?(): number;
  free(): void;
}

/** The subset of the wasm module's exports the worker uses (after init). */
export interface WasmApi {
  /** The incremental generator the worker keeps (one per worker). */
  Session: new () => WasmSession;
  registry_json(): string;
  presets_json(): string;
  core_version(): string;
  generate(paramsJson: string): WasmTree;
  /** `generate` calling `progress(fraction)` during growth (optional: fakes may omit it). */
  generate_with_progress?(paramsJson: string, progress: (fraction: number) => void): WasmTree;
  take_panic(): string | undefined;
  leaf_inspect?(paramsJson: string, step: number, triangulation: boolean): string;
  leaf_presets_json?(): string;
  /**
   * The procedural bark maps of bark type `kind`: colour, normal, occlusion-roughness-metal
   * (RGBA8, `size`² each, one after the other; optional so that fakes may leave them out).
   */
  bark_maps?(kind: number, size: number): Uint8Array;
  /** How bark type `kind` lies on a stem, as JSON (`BarkStyle`). */
  bark_style_json?(kind: number): string;
  /** The end grain of bark type `kind`: colour then normal map (RGBA8, `size`² each). */
  end_grain_maps?(kind: number, size: number): Uint8Array;
}
