/** Worker side of the LOD request: runs `generate_lods` and packs every level for transfer. */
import type { WasmApi } from '../core/types';
import { coreInput } from '../core/editsJson';
import { volumeToCore } from '../core/volumes';
import type {
  BakedLeafBuffers,
  LodBuffers,
  LodLevelBuffers,
  LodMeta,
  LodsRequest,
  LodsResponse,
  LodWasmApi,
  WasmLods,
} from './types';
import { CLUMP_SIZE, clumpAtlas } from './clump';

/** Seed of the clump atlas of a tree of seed 0. */
const CLUMP_SEED = 7;

/** Level `level`'s leaves baked by the core (`GeneratedLods.baked_leaves`), or none. */
function bakedLeaves(lods: WasmLods, level: number): BakedLeafBuffers | undefined {
  if (typeof lods.baked_leaves !== 'function') {
    throw new Error('this generator build cannot bake leaves');
  }
  const baked = lods.baked_leaves(level);
  try {
    const indices = baked.indices();
    if (indices.length === 0) return undefined;
    return {
      positions: baked.positions(),
      normals: baked.normals(),
      uvs: baked.uvs(),
      indices,
      colors: baked.colors(),
    };
  } finally {
    baked.free();
  }
}

/** Parses and checks `GeneratedLods.meta_json()`. */
export function parseLodMeta(text: string): LodMeta {
  const meta = JSON.parse(text) as LodMeta;
  if (!Array.isArray(meta.levels) || meta.levels.length !== 3 || typeof meta.hash !== 'string') {
    throw new Error('generate_lods returned malformed metadata');
  }
  return meta;
}

/**
 * Generates the tree of `request` with its levels of detail; returns the response and the
 * buffers to transfer. Throws what `generate_lods` throws (a JSON `SylvaError` or a trap).
 */
export function lodsResponse(
  wasm: WasmApi & LodWasmApi,
  request: LodsRequest,
): [LodsResponse, Transferable[]] {
  if (typeof wasm.generate_lods !== 'function') {
    throw new Error('this generator build has no generate_lods');
  }
  const input = coreInput(request.params, request.volumes?.map(volumeToCore), request.edits);
  const lods = wasm.generate_lods(JSON.stringify(input));
  try {
    const meta = parseLodMeta(lods.meta_json());
    const levels: LodLevelBuffers[] = [0, 1, 2].map((i) => ({
      ...(request.bakeLeaves ? { bakedLeaves: bakedLeaves(lods, i) } : {}),
      positions: lods.positions(i),
      normals: lods.normals(i),
      uvs: lods.uvs(i),
      indices: lods.indices(i),
      shade: lods.shade(i),
      leafPositions: lods.leaf_positions(i),
      leafNormals: lods.leaf_normals(i),
      leafUvs: lods.leaf_uvs(i),
      leafIndices: lods.leaf_indices(i),
      leafMatrices: lods.leaf_matrices(i),
      leafColors: lods.leaf_colors(i),
      cloud: lods.cloud(i),
    }));
    const rgba = lods.leaf_texture();
    const size = meta.leaf_texture;
    const leafTexture =
      size && rgba.length === size[0] * size[1] * 4
        ? { width: size[0], height: size[1], rgba }
        : null;
    // The clouds' clump atlas, seeded by the tree's seed (a forest's trees differ).
    const clump = levels.some((l) => l.cloud.length > 0)
      ? { size: CLUMP_SIZE, rgba: clumpAtlas(leafTexture, CLUMP_SEED + (request.params.seed ?? 0)) }
      : null;
    const buffers: LodBuffers = { meta, levels, leafTexture, clump };
    const transfer: Transferable[] = levels.flatMap(({ bakedLeaves: baked, ...arrays }) => {
      const views: ArrayBufferView[] = Object.values(arrays);
      if (baked) views.push(baked.positions, baked.normals, baked.uvs, baked.indices, baked.colors);
      return views.map((a) => a.buffer as ArrayBuffer);
    });
    if (leafTexture) transfer.push(leafTexture.rgba.buffer as ArrayBuffer);
    if (clump) transfer.push(clump.rgba.buffer as ArrayBuffer);
    return [{ type: 'lods', id: request.id, lods: buffers }, transfer];
  } finally {
    lods.free();
  }
}
