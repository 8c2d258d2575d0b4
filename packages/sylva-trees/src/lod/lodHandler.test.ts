/**
 * The LOD worker's baked leaves are the core's: LOD0's baked mesh is the one a GLB exported with
 * `leaves: 'baked'` holds (same vertices, same bounds), and every level's has one copy of its
 * leaf mesh per leaf.
 */
import { describe, expect, it } from 'vitest';
import { CLUMP_SIZE, clumpAtlas } from './clump';
import { lodsResponse } from './lodHandler';
import type { LodWasmApi } from './types';
import type { WasmApi } from '../core/types';
import { loadWasm } from '../testing/realWasm';

const PARAMS = { levels: 2, seed: 3 };

interface Gltf {
  nodes: { name: string; mesh?: number }[];
  meshes: { primitives: { attributes: { POSITION: number } }[] }[];
  accessors: {
    bufferView: number;
    byteOffset?: number;
    componentType: number;
    count: number;
    min: number[];
    max: number[];
  }[];
  bufferViews: { byteOffset?: number }[];
}

/** The leaves' POSITION accessor of a GLB, and its floats. */
function glbLeafPositions(glb: Uint8Array): {
  count: number;
  min: number[];
  max: number[];
  floats: Float32Array;
} {
  const view = new DataView(glb.buffer, glb.byteOffset, glb.byteLength);
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(glb.slice(20, 20 + jsonLength))) as Gltf;
  const node = json.nodes.find((n) => n.name === 'leaves');
  const accessor =
    json.accessors[json.meshes[node?.mesh ?? -1]!.primitives[0]!.attributes.POSITION]!;
  expect(accessor.componentType).toBe(5126); // FLOAT
  const binStart = 20 + jsonLength + 8;
  const offset =
    binStart +
    (json.bufferViews[accessor.bufferView]!.byteOffset ?? 0) +
    (accessor.byteOffset ?? 0);
  const floats = new Float32Array(glb.slice(offset, offset + accessor.count * 12).buffer);
  return { count: accessor.count, min: accessor.min, max: accessor.max, floats };
}

function bounds(p: Float32Array): { min: number[]; max: number[] } {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < p.length; i++) {
    min[i % 3] = Math.min(min[i % 3]!, p[i]!);
    max[i % 3] = Math.max(max[i % 3]!, p[i]!);
  }
  return { min, max };
}

describe('baked leaves from the LOD worker', () => {
  const wasm = loadWasm() as WasmApi & LodWasmApi;

  it("LOD0 is the GLB export's baked leaf mesh; every level has a copy of its leaf per leaf", () => {
    const [response, transfer] = lodsResponse(wasm, {
      type: 'lods',
      id: 1,
      params: PARAMS,
      bakeLeaves: true,
    });
    const { levels, meta } = response.lods;
    for (const [i, level] of levels.slice(0, 2).entries()) {
      const baked = level.bakedLeaves;
      const leaves = level.leafColors.length / 3;
      expect(leaves, `LOD${i}`).toBe(meta.levels[i]!.leaves);
      expect(leaves, `LOD${i}`).toBeGreaterThan(0);
      expect(baked?.positions.length, `LOD${i}`).toBe(level.leafPositions.length * leaves);
      expect(baked?.indices.length, `LOD${i}`).toBe(level.leafIndices.length * leaves);
      expect(baked?.colors.length, `LOD${i}`).toBe(level.leafPositions.length * leaves);
      expect(transfer).toContain(baked?.positions.buffer);
    }
    expect(levels[2]?.bakedLeaves).toBeUndefined();

    const tree = wasm.generate(JSON.stringify(PARAMS));
    try {
      const glb = glbLeafPositions(
        tree.to_glb?.('{"textures":false,"leaves":"baked"}') ?? new Uint8Array(),
      );
      const baked = levels[0]!.bakedLeaves!.positions;
      expect(baked.length / 3).toBe(glb.count);
      expect(bounds(baked)).toEqual({ min: glb.min, max: glb.max });
      expect(baked).toEqual(glb.floats);
    } finally {
      tree.free();
    }
  });

  it('bakes nothing unless asked', () => {
    const [response] = lodsResponse(wasm, { type: 'lods', id: 2, params: PARAMS });
    expect(response.lods.levels.map((l) => l.bakedLeaves)).toEqual([
      undefined,
      undefined,
      undefined,
    ]);
  });

  it("sends the clouds' clump atlas, made from the tree's leaf and seeded by its seed", () => {
    const [a, transfer] = lodsResponse(wasm, { type: 'lods', id: 3, params: PARAMS });
    const clump = a.lods.clump;
    expect(a.lods.levels[2]!.cloud.length).toBeGreaterThan(0);
    expect(clump?.size).toBe(CLUMP_SIZE);
    expect(clump?.rgba).toEqual(clumpAtlas(a.lods.leafTexture, 7 + PARAMS.seed));
    expect(transfer).toContain(clump?.rgba.buffer);
    const [b] = lodsResponse(wasm, { type: 'lods', id: 4, params: { ...PARAMS, seed: 4 } });
    expect(b.lods.clump?.rgba).not.toEqual(clump?.rgba);
  });
});
