/**
 * The main thread's view of the current tree: the worker's session answers with only the
 * arrays that changed (`TreeUpdate`); merging them into the previous full set gives the whole
 * tree again (`TreeBuffers`) for the viewer, the LOD controller and the growth overlay. Pure:
 * arrays are shared, never copied.
 */
import type { FoliageBuffers, TreeBuffers, TreeUpdate } from '../core/types';

/** The update that draws `tree` from nothing (every array present). */
export function updateOf(tree: TreeBuffers): TreeUpdate {
  const f = tree.foliage;
  return {
    meta: tree.meta,
    bark: {
      positions: tree.positions,
      normals: tree.normals,
      uvs: tree.uvs,
      indices: tree.indices,
      wind: tree.wind ?? new Float32Array(0),
      ...(tree.pick ? { pick: tree.pick } : {}),
    },
    envelope: tree.envelope,
    markers: tree.markers ?? new Float32Array(0),
    instances: f
      ? { matrices: f.matrices, colors: f.colors }
      : { matrices: new Float32Array(0), colors: new Float32Array(0) },
    organs: tree.organs ?? [],
    leafTint: tree.leafTint ?? null,
    ...(f
      ? {
          leafMesh: { positions: f.positions, normals: f.normals, uvs: f.uvs, indices: f.indices },
        }
      : {}),
    ...(f?.texture ? { leafTexture: f.texture } : {}),
    ...(tree.bark ? { barkTextures: tree.bark } : {}),
    ...(tree.endGrain ? { endGrain: tree.endGrain } : {}),
    shade: tree.shade ?? new Uint8Array(0),
  };
}

const EMPTY_F32 = new Float32Array(0);
const EMPTY_U32 = new Uint32Array(0);

/**
 * `current` with `update` applied. The first update (no `current`) must carry the bark. The
 * leaf texture is present only when this update brought one (null: unchanged).
 */
export function mergeUpdate(current: TreeBuffers | null, update: TreeUpdate): TreeBuffers {
  const bark = update.bark ?? current;
  if (!bark) throw new Error('the first tree update must carry the bark');
  const old = current?.foliage;
  const leafMesh = update.leafMesh ?? old;
  const instances = update.instances ?? old;
  const foliage: FoliageBuffers = {
    positions: leafMesh?.positions ?? EMPTY_F32,
    normals: leafMesh?.normals ?? EMPTY_F32,
    uvs: leafMesh?.uvs ?? EMPTY_F32,
    indices: leafMesh?.indices ?? EMPTY_U32,
    matrices: instances?.matrices ?? EMPTY_F32,
    colors: instances?.colors ?? EMPTY_F32,
    texture: update.leafTexture ?? null,
    leafHash: update.meta.leaf_texture ? update.meta.leaf_hash : '',
  };
  const wind = update.bark ? update.bark.wind : current?.wind;
  const pick = update.bark ? update.bark.pick : current?.pick;
  const markers = update.markers ?? current?.markers;
  const textures = update.barkTextures ?? current?.bark;
  const endGrain = update.endGrain ?? current?.endGrain;
  const shade = update.shade ?? current?.shade;
  const organs = update.organs ?? current?.organs ?? [];
  const leafTint = update.leafTint !== undefined ? update.leafTint : (current?.leafTint ?? null);
  return {
    positions: bark.positions,
    normals: bark.normals,
    uvs: bark.uvs,
    indices: bark.indices,
    envelope: update.envelope ?? current?.envelope ?? EMPTY_F32,
    meta: update.meta,
    foliage,
    organs,
    leafTint,
    ...(wind ? { wind } : {}),
    ...(markers ? { markers } : {}),
    ...(textures ? { bark: textures } : {}),
    ...(endGrain ? { endGrain } : {}),
    ...(shade ? { shade } : {}),
    ...(pick ? { pick } : {}),
  };
}
