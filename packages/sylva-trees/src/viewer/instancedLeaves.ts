/**
 * Leaves as a three.js `InstancedMesh` of the core's leaf mesh, for leaf meshes too big to pull
 * (`Foliage` picks): the instance matrices and tints wrap the transferred arrays (no per-leaf
 * loop on the main thread); arrays of the sizes already on the GPU are swapped in place, other
 * sizes get new objects and the old are disposed.
 */
import {
  BufferAttribute,
  BufferGeometry,
  type InstancedMesh,
  type Material,
  type Object3D,
} from 'three';
import type { LeafMeshBuffers } from '../core/types';
import { wrapInstances } from './instances';

/** Per-leaf arrays: column-major matrices (16 floats) and tints (3 floats). */
export interface LeafInstances {
  matrices: Float32Array;
  colors: Float32Array;
}

/** Owns the instanced leaf mesh and its leaf geometry. */
export class InstancedLeaves {
  private geometry: BufferGeometry | null = null;
  private mesh: InstancedMesh | null = null;

  constructor(
    private readonly parent: Object3D,
    private readonly material: Material,
    private readonly depthMaterial: () => Material | undefined,
  ) {}

  /** The mesh drawn (null: none). */
  get object(): InstancedMesh | null {
    return this.mesh;
  }

  /** Shows `instances` of `leaf`; `leafChanged`: `leaf` is new (else the geometry stays). */
  show(leaf: LeafMeshBuffers, leafChanged: boolean, instances: LeafInstances): void {
    if (leafChanged || !this.geometry) this.setLeafMesh(leaf);
    const count = instances.colors.length / 3;
    const mesh = this.mesh;
    if (mesh && mesh.count === count && mesh.geometry === this.geometry) {
      if (mesh.instanceMatrix.array !== instances.matrices) {
        mesh.instanceMatrix.array = instances.matrices;
        mesh.instanceMatrix.needsUpdate = true;
      }
      if (mesh.instanceColor && mesh.instanceColor.array !== instances.colors) {
        mesh.instanceColor.array = instances.colors;
        mesh.instanceColor.needsUpdate = true;
      }
      return;
    }
    this.remove();
    if (!this.geometry) return;
    const next = wrapInstances(
      this.geometry,
      this.material,
      instances.matrices,
      instances.colors,
      count,
    );
    // Bounds over every instance would loop over the leaves: the tree is framed by its bark.
    next.frustumCulled = false;
    const depth = this.depthMaterial();
    if (depth) next.customDepthMaterial = depth;
    next.castShadow = true;
    next.receiveShadow = true;
    this.mesh = next;
    this.parent.add(next);
  }

  /** The leaf mesh: swapped into the current geometry when the sizes match, else a new one. */
  private setLeafMesh(leaf: LeafMeshBuffers): void {
    const g = this.geometry;
    const same = (name: string, array: Float32Array) =>
      (g?.getAttribute(name) as BufferAttribute | undefined)?.array.length === array.length;
    if (
      g &&
      same('position', leaf.positions) &&
      same('normal', leaf.normals) &&
      same('uv', leaf.uvs) &&
      g.getIndex()?.array.length === leaf.indices.length
    ) {
      for (const [name, array] of [
        ['position', leaf.positions],
        ['normal', leaf.normals],
        ['uv', leaf.uvs],
      ] as const) {
        const attribute = g.getAttribute(name) as BufferAttribute;
        attribute.array = array;
        attribute.needsUpdate = true;
      }
      const index = g.getIndex() as BufferAttribute;
      index.array = leaf.indices;
      index.needsUpdate = true;
      return;
    }
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(leaf.positions, 3));
    geometry.setAttribute('normal', new BufferAttribute(leaf.normals, 3));
    geometry.setAttribute('uv', new BufferAttribute(leaf.uvs, 2));
    geometry.setIndex(new BufferAttribute(leaf.indices, 1));
    this.remove();
    this.geometry?.dispose();
    this.geometry = geometry;
  }

  /** Removes the mesh (its instance buffers go with it; the leaf geometry stays). */
  remove(): void {
    if (!this.mesh) return;
    this.parent.remove(this.mesh);
    this.mesh.dispose();
    this.mesh = null;
  }

  /** Removes the mesh and frees the leaf geometry. */
  dispose(): void {
    this.remove();
    this.geometry?.dispose();
    this.geometry = null;
  }
}
