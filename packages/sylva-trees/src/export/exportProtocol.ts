/**
 * Worker messages of the mesh export (GLB, OBJ + MTL). The app asks a worker of its generation
 * pool (`SylvaTree` its own export worker), never the interactive one: an export regenerates the
 * current params and returns the files, as transferable bytes or (GLB) as a Blob made in the
 * worker straight from the core's memory.
 */
import type { Edit } from '../core/edits';
import type { Params, VolumePrimitive } from '../core/types';

/**
 * File formats the core may export: a GLB, a zipped OBJ, the GLB with the growth animation
 * (`glb-growth`: morph targets from year 0 to the Age, leaves baked; docs/formats.md "Growth
 * animation"), the growth as a zip of one GLB per whole year (`glb-years`), or the levels of
 * detail (`lods`: LOD0, LOD1, LOD2 as GLBs and the impostor GLB, zipped).
 */
export type ExportFormat = 'glb' | 'obj' | 'glb-growth' | 'glb-years' | 'lods';

/**
 * How leaves go into a GLB: one leaf mesh instanced per leaf (`EXT_mesh_gpu_instancing`, for
 * engines), every leaf merged into one leaf mesh (`baked`, for Blender and other editors), or
 * left out.
 */
export type LeafExport = 'instanced' | 'baked' | 'none';

/** Ask the worker to regenerate `params` and export the tree. */
export interface ExportRequest {
  type: 'export';
  id: number;
  params: Params;
  volumes?: VolumePrimitive[];
  /** The hand edit list (absent when empty). */
  edits?: Edit[];
  format: ExportFormat;
  /** The core's `{"leaves": ...}` export option (GLB; default `instanced`). */
  leaves?: LeafExport;
  /**
   * The core's `{"strict": true}` export option (GLB): no glTF extension, for Godot and other
   * strict importers (float normals and tangents, instanced leaves baked). Named `STEM-strict.glb`.
   */
  strict?: boolean;
  /** File stem: the OBJ names its MTL and textures after it (default `tree`). */
  name?: string;
  /**
   * `lods`: the impostor GLB made on the page from its atlas (baked with WebGL there), stored in
   * the ZIP after the three levels as `STEM_impostor.glb`.
   */
  impostor?: Uint8Array;
}

/**
 * One exported file (name as the files refer to each other, e.g. the OBJ's `mtllib`): its bytes,
 * transferred, or a Blob. A GLB comes as a Blob the worker made from a view of the core's memory
 * (`to_glb_file`): one copy of a file that may be hundreds of MB, and none on the main thread.
 */
export type ExportedFile = { name: string; mime: string } & (
  { bytes: Uint8Array } | { blob: Blob }
);

/**
 * The exported files of request `id`, with the tree's content hash: one GLB (`NAME-growth.glb`
 * for the growth animation), for an OBJ one ZIP (`NAME-obj.zip`) holding the OBJ, its MTL and
 * the textures the MTL names, for the years one ZIP (`NAME-years.zip`) of `year_001.glb`, ...,
 * or for `lods` one ZIP (`NAME-lods.zip`, `NAME-lods-strict.zip`) of the level GLBs and the
 * impostor.
 */
export interface ExportResponse {
  type: 'exported';
  id: number;
  format: ExportFormat;
  hash: string;
  files: ExportedFile[];
}
