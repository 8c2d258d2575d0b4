import { afterEach, describe, expect, it, vi } from 'vitest';
import {
  BufferGeometry,
  Group,
  InstancedBufferAttribute,
  InstancedMesh,
  Matrix4,
  MeshBasicMaterial,
  type Mesh,
} from 'three';
import { Foliage } from './Foliage';
import { wrapInstances } from './instances';

describe('wrapInstances', () => {
  afterEach(() => vi.restoreAllMocks());

  it('wraps the given arrays without a per-instance loop', () => {
    // three.js's constructor calls setMatrixAt once per instance; 50,000 leaves would mean
    // 50,000 calls on the main thread for an array that is thrown away.
    const setMatrixAt = vi.spyOn(InstancedMesh.prototype, 'setMatrixAt');
    const n = 50_000;
    const matrices = new Float32Array(16 * n);
    const colors = new Float32Array(3 * n);
    new Matrix4().makeTranslation(1, 2, 3).toArray(matrices, 16 * 7);
    const mesh = wrapInstances(new BufferGeometry(), new MeshBasicMaterial(), matrices, colors);
    expect(setMatrixAt).not.toHaveBeenCalled();
    expect(mesh.count).toBe(n);
    expect(mesh.instanceMatrix.array).toBe(matrices);
    expect(mesh.instanceColor?.array).toBe(colors);
    const m = new Matrix4();
    mesh.getMatrixAt(7, m);
    expect(m.elements.slice(12, 15)).toEqual([1, 2, 3]);
  });

  it("is not how the viewer's leaves are drawn: they are pulled, one plain draw", () => {
    const setMatrixAt = vi.spyOn(InstancedMesh.prototype, 'setMatrixAt');
    const parent = new Group();
    const n = 1000;
    new Foliage(parent).set({
      positions: new Float32Array(9),
      normals: new Float32Array(9),
      uvs: new Float32Array(6),
      indices: new Uint32Array([0, 1, 2]),
      matrices: new Float32Array(16 * n),
      colors: new Float32Array(3 * n),
      texture: null,
      leafHash: '',
    });
    expect(setMatrixAt).not.toHaveBeenCalled();
    const leaves = parent.children[0] as Mesh;
    expect((leaves as Partial<InstancedMesh>).isInstancedMesh).toBeUndefined();
    expect(Object.keys(leaves.geometry.attributes)).toEqual([]);
    expect(leaves.geometry.drawRange.count).toBe(3 * n);
  });

  it('shares an attribute and draws fewer instances than it holds', () => {
    const shared = new InstancedBufferAttribute(new Float32Array(16 * 10), 16);
    const mesh = wrapInstances(new BufferGeometry(), new MeshBasicMaterial(), shared, null, 0);
    expect(mesh.instanceMatrix).toBe(shared);
    expect(mesh.instanceColor).toBeNull();
    expect(mesh.count).toBe(0);
  });
});
