/**
 * Session updates reach the GPU objects in place: same-size arrays are swapped into the
 * existing attributes (no new buffers), other sizes get new objects and the old are disposed;
 * leaves are copied into their textures, replaced only when the leaves outgrow or halve them.
 */
import {
  Group,
  type BufferAttribute,
  type DataTexture,
  type InstancedMesh,
  type Mesh,
  type MeshStandardMaterial,
} from 'three';
import { describe, expect, it } from 'vitest';
import type { BarkBuffers, TreeMeta } from '../core/types';
import { Foliage, LEAF_MATRICES_KEY, PULL_MAX_INDICES } from './Foliage';
import { LEAVES_PER_ROW, ROW_STEP, type LeafPullUniforms } from './leafPull';
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
  holes: 0,
  envelope: [],
  leaves: 0,
  leaf_hash: '0000000000000000',
  leaf_texture: null,
  bark_type: 0,
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

function leaves(count: number, value = 0) {
  return {
    matrices: new Float32Array(count * 16).fill(value),
    colors: new Float32Array(count * 3).fill(1),
  };
}

const LEAF_MESH = {
  positions: new Float32Array(9),
  normals: new Float32Array(9),
  uvs: new Float32Array(6),
  indices: new Uint32Array([0, 1, 2]),
};

function meshOf(parent: Group): Mesh {
  const m = parent.children[0] as Mesh | undefined;
  if (!m) throw new Error('no leaves');
  return m;
}

/** The texture a pulled-leaf uniform points at. */
function uniformTexture(mesh: Mesh, name: keyof LeafPullUniforms): DataTexture {
  const material = mesh.material as MeshStandardMaterial;
  const shader = {
    uniforms: {} as Record<string, { value: unknown }>,
    vertexShader: 'void main() {',
  };
  material.onBeforeCompile(shader as never, null as never);
  return shader.uniforms[name]!.value as DataTexture;
}

describe('foliage in place', () => {
  it('new placements of the same count go into the same mesh and textures', () => {
    const parent = new Group();
    const foliage = new Foliage(parent);
    foliage.update({ instances: leaves(5), leafMesh: LEAF_MESH });
    const mesh = meshOf(parent);
    const texture = uniformTexture(mesh, 'sylvaLeafMatrices');
    const version = texture.version;
    const next = leaves(5, 7);
    foliage.update({ instances: next });
    expect(meshOf(parent)).toBe(mesh);
    expect(uniformTexture(mesh, 'sylvaLeafMatrices')).toBe(texture);
    expect(texture.version).toBe(version + 1);
    expect(Array.from((texture.image.data as Float32Array).subarray(0, 80))).toEqual(
      Array.from(next.matrices),
    );
    expect(mesh.userData[LEAF_MATRICES_KEY]).toBe(next.matrices);
    expect(mesh.geometry.drawRange.count).toBe(5 * 3);
  });

  it('leaf counts within the allocated rows keep the texture; outgrowing or halving replaces it', () => {
    const parent = new Group();
    const foliage = new Foliage(parent);
    foliage.update({ instances: leaves(5), leafMesh: LEAF_MESH });
    const mesh = meshOf(parent);
    const texture = uniformTexture(mesh, 'sylvaLeafMatrices');
    expect(texture.image.height).toBe(ROW_STEP);
    let disposed = 0;
    texture.addEventListener('dispose', () => disposed++);
    // A drag of the leaf count: every step copies into the same texture.
    for (const n of [7, LEAVES_PER_ROW + 1, ROW_STEP * LEAVES_PER_ROW]) {
      foliage.update({ instances: leaves(n) });
      expect(uniformTexture(mesh, 'sylvaLeafMatrices'), `${n}`).toBe(texture);
      expect(mesh.geometry.drawRange.count).toBe(n * 3);
    }
    expect(disposed).toBe(0);
    foliage.update({ instances: leaves(ROW_STEP * LEAVES_PER_ROW + 1) });
    const bigger = uniformTexture(mesh, 'sylvaLeafMatrices');
    expect(bigger).not.toBe(texture);
    expect(bigger.image.height).toBe(2 * ROW_STEP);
    expect(disposed).toBe(1);
    foliage.update({ instances: leaves(3) });
    expect(uniformTexture(mesh, 'sylvaLeafMatrices').image.height).toBe(ROW_STEP);
    expect(meshOf(parent)).toBe(mesh);
    expect(foliage.count).toBe(3);
  });

  it('a new leaf mesh goes into the leaf-mesh texture and sets the vertices drawn', () => {
    const parent = new Group();
    const foliage = new Foliage(parent);
    foliage.update({ instances: leaves(2), leafMesh: LEAF_MESH });
    const bigger = {
      positions: new Float32Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]),
      normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]),
      uvs: new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]),
      indices: new Uint32Array([0, 1, 2, 0, 2, 3]),
    };
    foliage.update({ leafMesh: bigger });
    const mesh = meshOf(parent);
    expect(mesh.geometry.drawRange.count).toBe(2 * 6);
    const data = uniformTexture(mesh, 'sylvaLeafMesh').image.data as Float32Array;
    // Row 0: corner 2's position and u; row 1: its normal and v; row 2: the triangle list.
    expect(Array.from(data.subarray(8, 12))).toEqual([1, 1, 0, 1]);
    expect(Array.from(data.subarray((6 + 2) * 4, (6 + 2) * 4 + 4))).toEqual([0, 0, 1, 1]);
    expect([0, 1, 2, 3, 4, 5].map((k) => data[(12 + k) * 4])).toEqual([0, 1, 2, 0, 2, 3]);
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
    expect(parent.children).toHaveLength(1);
  });

  it('a leaf mesh of more than PULL_MAX_INDICES indices is instanced, in place; back to pulled', () => {
    const parent = new Group();
    const foliage = new Foliage(parent);
    const triangles = PULL_MAX_INDICES / 3 + 1;
    const big = {
      positions: new Float32Array(9 * triangles),
      normals: new Float32Array(9 * triangles),
      uvs: new Float32Array(6 * triangles),
      indices: Uint32Array.from({ length: 3 * triangles }, (_, i) => i),
    };
    foliage.update({ instances: leaves(5), leafMesh: big });
    const mesh = meshOf(parent) as InstancedMesh;
    expect(mesh.isInstancedMesh).toBe(true);
    expect(mesh.count).toBe(5);
    const next = leaves(5, 3);
    foliage.update({ instances: next });
    expect(meshOf(parent)).toBe(mesh);
    expect(mesh.instanceMatrix.array).toBe(next.matrices);
    expect(mesh.instanceColor?.array).toBe(next.colors);
    foliage.update({ instances: leaves(6) });
    expect(parent.children).toHaveLength(1);
    expect((meshOf(parent) as InstancedMesh).count).toBe(6);
    // A small leaf again: pulled, the instanced mesh gone.
    foliage.update({ leafMesh: LEAF_MESH });
    expect(parent.children).toHaveLength(1);
    expect((meshOf(parent) as Partial<InstancedMesh>).isInstancedMesh).toBeUndefined();
    expect(meshOf(parent).geometry.drawRange.count).toBe(6 * 3);
    expect(foliage.count).toBe(6);
  });

  it('leaving pulled leaves (instanced or bare) releases their textures; pulled again makes new ones', () => {
    const parent = new Group();
    const foliage = new Foliage(parent);
    foliage.update({ instances: leaves(4), leafMesh: LEAF_MESH });
    const mesh = meshOf(parent);
    const names = ['sylvaLeafMatrices', 'sylvaLeafTints', 'sylvaLeafMesh'] as const;
    const textures = names.map((n) => uniformTexture(mesh, n));
    let disposed = 0;
    for (const t of textures) t.addEventListener('dispose', () => disposed++);
    const big = {
      positions: new Float32Array(9 * 9),
      normals: new Float32Array(9 * 9),
      uvs: new Float32Array(6 * 9),
      indices: Uint32Array.from({ length: 27 }, (_, i) => i),
    };
    foliage.update({ leafMesh: big });
    expect((meshOf(parent) as InstancedMesh).isInstancedMesh).toBe(true);
    expect(disposed).toBe(3);
    foliage.update({ leafMesh: LEAF_MESH });
    const again = meshOf(parent);
    for (const [k, n] of names.entries()) {
      const t = uniformTexture(again, n);
      expect(t, n).not.toBe(textures[k]);
      expect(t, n).not.toBeNull();
    }
    expect(
      Array.from(
        (uniformTexture(again, 'sylvaLeafMatrices').image.data as Float32Array).subarray(0, 64),
      ),
    ).toEqual(Array.from(leaves(4).matrices));
    expect(again.geometry.drawRange.count).toBe(4 * 3);
  });
});
