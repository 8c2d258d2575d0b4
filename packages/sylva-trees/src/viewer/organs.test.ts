/**
 * The organ meshes: one InstancedMesh per set with instances, wrapping the transferred arrays
 * (no copies), a two-sided material of the set's sRGB colour and roughness with the tints as
 * instanceColor; a new list replaces the old and frees its geometries and materials; the tree
 * object puts them under its group, swaying with the leaves, and not pickable.
 */
import {
  Color,
  DoubleSide,
  Group,
  Raycaster,
  SRGBColorSpace,
  Vector3,
  type InstancedMesh,
  type MeshStandardMaterial,
} from 'three';
import { describe, expect, it } from 'vitest';
import type { OrganSetBuffers, TreeBuffers, TreeMeta } from '../core/types';
import { ORGAN_MESH_PREFIX, OrganSets } from './organs';
import { TreeObject } from './TreeObject';
import { createWindUniforms, patchWindShader } from './wind';

/** A set of `count` one-triangle parts at x = 0, 1, 2, ... */
function set(
  name: string,
  count: number,
  color: [number, number, number] = [0.5, 0.4, 0.2],
): OrganSetBuffers {
  const matrices = new Float32Array(count * 16);
  for (let i = 0; i < count; i++) {
    matrices.set([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, i, 1, 0, 1], i * 16);
  }
  return {
    kind: 'fruit',
    name,
    color,
    roughness: 0.45,
    positions: new Float32Array([0, 0, 0, 0.02, 0, 0, 0, 0.02, 0]),
    normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1]),
    indices: new Uint32Array([0, 1, 2]),
    matrices,
    colors: new Float32Array(count * 3).fill(0.9),
  };
}

/** Counts `dispose` events of the meshes' geometries and materials. */
function watchDisposal(meshes: readonly InstancedMesh[]): {
  geometries: number;
  materials: number;
} {
  const seen = { geometries: 0, materials: 0 };
  for (const m of meshes) {
    m.geometry.addEventListener('dispose', () => seen.geometries++);
    (m.material as MeshStandardMaterial).addEventListener('dispose', () => seen.materials++);
  }
  return seen;
}

describe('organ sets in the viewer', () => {
  it('draws each set as an InstancedMesh over its own arrays', () => {
    const parent = new Group();
    const organs = new OrganSets(parent);
    const acorns = set('acorns', 4, [0.48, 0.4, 0.17]);
    organs.set([acorns, set('acorn cups', 4), set('nothing', 0)]);
    const meshes = organs.objects;
    expect(meshes.map((m) => m.name)).toEqual([
      `${ORGAN_MESH_PREFIX}acorns`,
      `${ORGAN_MESH_PREFIX}acorn cups`,
    ]);
    expect(parent.children).toEqual(meshes);
    const m = meshes[0]!;
    expect(m.count).toBe(4);
    expect(m.instanceMatrix.array).toBe(acorns.matrices);
    expect(m.instanceColor?.array).toBe(acorns.colors);
    expect(m.geometry.getAttribute('position').array).toBe(acorns.positions);
    expect(m.geometry.getIndex()?.array).toBe(acorns.indices);
    const material = m.material as MeshStandardMaterial;
    expect(material.side).toBe(DoubleSide);
    expect(material.roughness).toBe(0.45);
    expect(material.color.getHex()).toBe(
      new Color().setRGB(0.48, 0.4, 0.17, SRGBColorSpace).getHex(),
    );
    // The sRGB colour is stored linear by three.js: darker numbers than given.
    expect(material.color.r).toBeLessThan(0.48);
    expect(m.userData.organKind).toBe('fruit');
  });

  it('a new list replaces the old and disposes its geometries and materials', () => {
    const parent = new Group();
    const organs = new OrganSets(parent);
    organs.set([set('a', 2), set('b', 3)]);
    const old = [...organs.objects];
    const seen = watchDisposal(old);
    organs.set([set('c', 5)]);
    expect(seen).toEqual({ geometries: 2, materials: 2 });
    expect(parent.children.map((c) => c.name)).toEqual([`${ORGAN_MESH_PREFIX}c`]);
    const last = watchDisposal(organs.objects);
    organs.set([]);
    expect(parent.children).toEqual([]);
    expect(last).toEqual({ geometries: 1, materials: 1 });
  });

  it('the tree object shows them under its group, with wind, and keeps them out of picking', () => {
    const tree = new TreeObject();
    const meta: TreeMeta = {
      vertices: 3,
      triangles: 1,
      hash: '',
      bounds: { min: [0, 0, 0], max: [1, 2, 1] },
      groups: [{ material: 'bark', start: 0, count: 3 }],
      stage_ms: {},
      total_ms: 1,
      stems: 1,
      holes: 0,
      envelope: [],
      leaves: 0,
      leaf_hash: '0000000000000000',
      leaf_texture: null,
      bark_type: 0,
    };
    const buffers: TreeBuffers = {
      positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 2, 0]),
      normals: new Float32Array(9),
      uvs: new Float32Array(6),
      indices: new Uint32Array([0, 1, 2]),
      envelope: new Float32Array(0),
      meta,
      organs: [set('buds', 3)],
    };
    tree.setTree(buffers);
    const [buds] = tree.organMeshes;
    expect(buds?.parent).toBe(tree.group);
    expect(tree.buffers?.organs?.length).toBe(1);
    // Swaying with their anchors, without the leaves' flutter (parts are in metres).
    expect((buds!.material as MeshStandardMaterial).customProgramCacheKey()).toBe(
      'sylva-wind-organs-sylva-soft-shadows',
    );
    const shader = {
      vertexShader: '#include <common>\nvoid main() {\n#include <begin_vertex>\n}',
      uniforms: {},
    };
    patchWindShader(shader, createWindUniforms(), 'organs');
    expect(shader.vertexShader).toContain('#define WIND_NO_FLUTTER');
    const ray = new Raycaster(new Vector3(1, 1, 5), new Vector3(0, 0, -1));
    expect(ray.intersectObject(buds!)).toEqual([]);
    // An update without organs keeps them; an empty list removes them.
    tree.apply({ meta });
    expect(tree.organMeshes.length).toBe(1);
    tree.apply({ meta, organs: [] });
    expect(tree.organMeshes.length).toBe(0);
    expect(tree.group.children.some((c) => c.name.startsWith(ORGAN_MESH_PREFIX))).toBe(false);
    tree.dispose();
  });
});
