/** A level's bark mesh takes the viewer's materials with the level's groups (cut faces too). */
import { MeshStandardMaterial } from 'three';
import { describe, expect, it } from 'vitest';
import type { MeshGroup } from 'sylva-trees/core';
import type { LodLevelBuffers } from 'sylva-trees/worker';
import { barkMesh } from './lodObjects';

function level(): LodLevelBuffers {
  const f = new Float32Array(0);
  return {
    positions: new Float32Array(12),
    normals: new Float32Array(12),
    uvs: new Float32Array(8),
    indices: new Uint32Array([0, 1, 2, 0, 2, 3]),
    shade: new Uint8Array(4),
    leafPositions: f,
    leafNormals: f,
    leafUvs: f,
    leafIndices: new Uint32Array(0),
    leafMatrices: f,
    leafColors: f,
    cloud: f,
  };
}

const GROUPS: MeshGroup[] = [
  { material: 'bark', start: 0, count: 3 },
  { material: 'cut_face', start: 3, count: 3 },
];

describe('LOD bark mesh', () => {
  it('draws the cut faces with the third of the viewer materials', () => {
    const materials = [0, 1, 2].map(() => new MeshStandardMaterial());
    const mesh = barkMesh(level(), materials, GROUPS);
    expect(mesh.material).toBe(materials);
    expect(mesh.geometry.groups).toEqual([
      { start: 0, count: 3, materialIndex: 0 },
      { start: 3, count: 3, materialIndex: 2 },
    ]);
  });

  it('one material, a short array or no groups: the whole mesh in the (first) material', () => {
    const one = new MeshStandardMaterial();
    for (const mesh of [
      barkMesh(level(), one, GROUPS),
      barkMesh(level(), [one], GROUPS),
      barkMesh(level(), [one, new MeshStandardMaterial(), new MeshStandardMaterial()]),
    ]) {
      expect(mesh.material).toBe(one);
      expect(mesh.geometry.groups).toEqual([]);
    }
  });
});
