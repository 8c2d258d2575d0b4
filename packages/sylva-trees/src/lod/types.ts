/** Levels of detail as they cross the worker boundary (`generate_lods` in the wasm binding). */
import type { Edit } from '../core/edits';
import type { LeafTextureBuffers, LodMeta, Params, VolumePrimitive } from '../core/types';

export type { LodLevelMeta, LodMeta } from '../core/types';

/** One level's buffers (bark tubes, instanced leaves, billboard-cloud quads). */
export interface LodLevelBuffers {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint32Array;
  /** Bark occlusion, one byte per vertex (255 = open sky), as LOD0's `TreeMesh.shade`. */
  shade: Uint8Array;
  leafPositions: Float32Array;
  leafNormals: Float32Array;
  leafUvs: Float32Array;
  leafIndices: Uint32Array;
  /** Column-major 4x4 per leaf. */
  leafMatrices: Float32Array;
  /** RGB per leaf. */
  leafColors: Float32Array;
  /** 13 floats per quad: centre xyz, u xyz, v xyz (half-axes), rgb, leaf density 0.05..1. */
  cloud: Float32Array;
  /** The leaves baked into one mesh, when the request asked for them (`bakeLeaves`). */
  bakedLeaves?: BakedLeafBuffers;
}

/**
 * A level's leaves as one mesh in tree space, baked in the worker by the core's exporter (what
 * a GLB with `leaves: 'baked'` holds); the forest draws it, as three.js cannot instance an
 * `InstancedMesh`.
 */
export interface BakedLeafBuffers {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint32Array;
  /** RGB per vertex (its leaf's tint). */
  colors: Float32Array;
}

/**
 * The billboard cloud's leaf-clump atlas (`clumpAtlas`): `size`² RGBA bytes, rows bottom-up,
 * sRGB, a 2×2 grid of cells by leaf density (`CELL_DENSITY`).
 */
export interface ClumpBuffers {
  size: number;
  rgba: Uint8Array;
}

/** A tree and its reduced levels, LOD0 first. */
export interface LodBuffers {
  meta: LodMeta;
  levels: LodLevelBuffers[];
  leafTexture: LeafTextureBuffers | null;
  /** The clump atlas the levels' billboard clouds are drawn with (null: no level has a cloud). */
  clump: ClumpBuffers | null;
}

/** Floats per billboard-cloud quad. */
export const QUAD_FLOATS = 13;

/** Main thread → worker: a tree with its levels of detail. */
export interface LodsRequest {
  type: 'lods';
  id: number;
  params: Params;
  volumes?: VolumePrimitive[];
  /** The hand edit list (absent when empty). */
  edits?: Edit[];
  /** Also bake each level's leaves into one mesh (`LodLevelBuffers.bakedLeaves`). */
  bakeLeaves?: boolean;
}

/** Worker → main thread: the levels (all arrays transferred). */
export interface LodsResponse {
  type: 'lods';
  id: number;
  lods: LodBuffers;
}

/** The `GeneratedLods` object of the wasm binding. */
export interface WasmLods {
  positions(level: number): Float32Array;
  normals(level: number): Float32Array;
  uvs(level: number): Float32Array;
  indices(level: number): Uint32Array;
  leaf_positions(level: number): Float32Array;
  leaf_normals(level: number): Float32Array;
  leaf_uvs(level: number): Float32Array;
  leaf_indices(level: number): Uint32Array;
  leaf_matrices(level: number): Float32Array;
  leaf_colors(level: number): Float32Array;
  shade(level: number): Uint8Array;
  cloud(level: number): Float32Array;
  /** The leaves of `level` baked into one mesh (optional: test fakes may lack it). */
  baked_leaves?(level: number): WasmBakedLeaves;
  leaf_texture(): Uint8Array;
  meta_json(): string;
  free(): void;
}

/** The `BakedLeafMesh` object of the wasm binding. */
export interface WasmBakedLeaves {
  positions(): Float32Array;
  normals(): Float32Array;
  uvs(): Float32Array;
  indices(): Uint32Array;
  colors(): Float32Array;
  free(): void;
}

/** The wasm export this feature needs (optional: older builds and test fakes lack it). */
export interface LodWasmApi {
  generate_lods?(paramsJson: string): WasmLods;
}
