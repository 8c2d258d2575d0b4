/**
 * Session updates reach the GPU objects in place: same-size arrays are swapped into the
 * existing attributes (no new buffers), other sizes get new objects and the old are disposed.
 */
import { Group, type BufferAttribute, type InstancedMesh } from 'three';
import { describe, expect, it } from 'vitest';
import type { BarkBuffers, TreeMeta } from '../core/types';
import { Foliage } from './Foliage';
import { buildTreeGeometry, updateTreeGeometry } from './geometry';

const META: TreeMeta = {
  vertices: 3,
  triangles: 1,
  hash: '',
  bounds: { min: [0, 0, 0], max: [1, 2, 1] },
  groups: [{ material: 'bark', start: 0, count: 3 }],
  stage_ms: {},
  total_ms: 1,
  stems: 1,
};

function bark(vertices: number, wind = true): BarkBuffers {
  return {
    positions: new Float32Array(vertices * 3).fill(1),
    normals: new Float32Array(vertices * 3),
    uvs: new Float32Array(vertices * 2),
    indices: new Uint32Array([0, 1, 2]),
    wind: new Float32Array(wind ? vertices * 8 : 0),
  };
}

describe('bark geometry in place', () => {
  it('swaps same-size arrays into the attributes and bumps their versions', () => {
    const first = bark(3);
    const geometry = buildTreeGeometry({ ...first, envelope: new Float32Array(0), meta: META });
    const position = geometry.getAttribute('position') as BufferAttribute;
    const before = position.version;
    const next = bark(3);
    const meta: TreeMeta = { ...META, bounds: { min: [0, 0, 0], max: [3, 3, 3] } };
    expect(updateTreeGeometry(geometry, next, meta)).toBe(true);
    expect(geometry.getAttribute('position')).toBe(position);
    expect(position.array).toBe(next.positions);
    expect(position.version).toBe(before + 1);
    expect(geometry.getIndex()?.array).toBe(next.indices);
    expect(geometry.getAttribute('windPivot').array).toBe(next.wind);
    expect(geometry.boundingBox?.max.x).toBe(3);
  });

  it('refuses other sizes or a change of wind data, changing nothing', () => {
    const first = bark(3);
    const geometry = buildTreeGeometry({ ...first, envelope: new Float32Array(0), meta: META });
    expect(updateTreeGeometry(geometry, bark(4), META)).toBe(false);
    expect(updateTreeGeometry(geometry, bark(3, false), META)).toBe(false);
    expect(geometry.getAttribute('position').array).toBe(first.positions);
  });
});

function leaves(count: number) {
  return {
    matrices: new Float32Array(count * 16),
    colors: new Float32Array(count * 3).fill(1),
  };
}

const LEAF_MESH = {
  positions: new Float32Array(9),
  normals: new Float32Array(9),
  uvs: new Float32Array(6),
  indices: new Uint32Array([0, 1, 2]),
};

function meshOf(parent: Group): InstancedMesh {
  const m = parent.children[0] as InstancedMesh | undefined;
  if (!m) throw new Error('no leaves');
  return m;
}

describe('foliage in place', () => {
  it('new placements of the same count go into the same instanced mesh', () => {
    const parent = new Group();
    const foliage = new Foliage(parent);
    foliage.update({ instances: leaves(5), leafMesh: LEAF_MESH });
    const mesh = meshOf(parent);
    const next = leaves(5);
    foliage.update({ instances: next });
    expect(meshOf(parent)).toBe(mesh);
    expect(mesh.instanceMatrix.array).toBe(next.matrices);
    expect(mesh.instanceColor?.array).toBe(next.colors);
  });

  it('another count makes a new mesh and disposes the old; the leaf geometry stays', () => {
    const parent = new Group();
    const foliage = new Foliage(parent);
    foliage.update({ instances: leaves(5), leafMesh: LEAF_MESH });
    const mesh = meshOf(parent);
    let disposed = 0;
    mesh.addEventListener('dispose', () => disposed++);
    let geometryDisposed = 0;
    mesh.geometry.addEventListener('dispose', () => geometryDisposed++);
    foliage.update({ instances: leaves(7) });
    expect(parent.children).toHaveLength(1);
    expect(meshOf(parent)).not.toBe(mesh);
    expect(meshOf(parent).count).toBe(7);
    expect(meshOf(parent).geometry).toBe(mesh.geometry);
    expect(disposed).toBe(1);
    expect(geometryDisposed).toBe(0);
  });

  it('a new leaf mesh of the same size is swapped in; another size replaces the geometry', () => {
    const parent = new Group();
    const foliage = new Foliage(parent);
    foliage.update({ instances: leaves(2), leafMesh: LEAF_MESH });
    const geometry = meshOf(parent).geometry;
    const same = { ...LEAF_MESH, positions: new Float32Array(9).fill(2) };
    foliage.update({ leafMesh: same });
    expect(meshOf(parent).geometry).toBe(geometry);
    expect(geometry.getAttribute('position').array).toBe(same.positions);
    let disposed = 0;
    geometry.addEventListener('dispose', () => disposed++);
    const bigger = {
      positions: new Float32Array(12),
      normals: new Float32Array(12),
      uvs: new Float32Array(8),
      indices: new Uint32Array([0, 1, 2, 0, 2, 3]),
    };
    foliage.update({ leafMesh: bigger });
    expect(meshOf(parent).geometry).not.toBe(geometry);
    expect(meshOf(parent).geometry.getIndex()?.count).toBe(6);
    expect(disposed).toBe(1);
    expect(foliage.count).toBe(2);
  });

  it('a bare tree removes the leaves, and leaves come back', () => {
    const parent = new Group();
    const foliage = new Foliage(parent);
    foliage.update({ instances: leaves(2), leafMesh: LEAF_MESH });
    foliage.update({
      instances: leaves(0),
      leafMesh: { ...LEAF_MESH, indices: new Uint32Array(0), positions: new Float32Array(0) },
    });
    expect(parent.children).toHaveLength(0);
    expect(foliage.count).toBe(0);
    foliage.update({ instances: leaves(3), leafMesh: LEAF_MESH });
    expect(foliage.count).toBe(3);
  });
});
