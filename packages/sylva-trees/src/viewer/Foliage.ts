/**
 * The leaves of the tree: one `InstancedMesh` of the core's leaf geometry, with the instance
 * matrices and colours taken straight from the transferred typed arrays (no per-leaf loop on
 * the main thread) and a double-sided material that reads as thin leaf tissue: the baked leaf
 * texture with an alpha test, plus a dim emissive copy of it standing in for light shining
 * through the blade from behind.
 */
import type { DataTexture, InstancedMesh } from 'three';
import {
  BufferAttribute,
  BufferGeometry,
  DoubleSide,
  MeshStandardMaterial,
  type Material,
  type Object3D,
} from 'three';
import type {
  FoliageBuffers,
  LeafMeshBuffers,
  LeafTextureBuffers,
  TreeUpdate,
} from '../core/types';
import { wrapInstances } from './instances';
import { leafTexture as makeLeafTexture } from './leafTexture';

type Instances = NonNullable<TreeUpdate['instances']>;

/** Strength of the leaf's dim emissive copy of its texture (light shining through the blade). */
export const LEAF_TRANSLUCENCY = 0.22;

/** Owns the leaf mesh, texture and material. */
export class Foliage {
  /** The leaf material (the viewer patches it with wind). */
  readonly material = new MeshStandardMaterial({
    color: '#ffffff',
    roughness: 0.7,
    side: DoubleSide,
    alphaTest: 0.5,
    emissive: '#ffffff',
    emissiveIntensity: LEAF_TRANSLUCENCY,
  });
  private texture: DataTexture | null = null;
  private mesh: InstancedMesh | null = null;
  /** The leaf mesh every instance draws (kept across placement changes). */
  private geometry: BufferGeometry | null = null;
  /** The current per-leaf matrices and tints. */
  private instances: Instances | null = null;
  /** Shadow depth material given to every leaf mesh (the wind's, so shadows move too). */
  depthMaterial: Material | undefined = undefined;

  constructor(private readonly parent: Object3D) {}

  /** Number of leaves shown. */
  get count(): number {
    return this.mesh?.count ?? 0;
  }

  /** Replaces the leaves (an empty buffer set removes them). */
  set(buffers: FoliageBuffers | undefined): void {
    this.removeMesh();
    this.geometry?.dispose();
    this.geometry = null;
    this.instances = null;
    if (!buffers) return;
    this.update({
      instances: { matrices: buffers.matrices, colors: buffers.colors },
      leafMesh: buffers,
      ...(buffers.texture ? { leafTexture: buffers.texture } : {}),
    });
  }

  /**
   * Applies the leaf parts of a session update; absent parts stay. Arrays of the sizes already
   * on the GPU are swapped in place (no new buffers); other sizes get new objects and the old
   * ones are disposed.
   */
  update(update: Pick<TreeUpdate, 'instances' | 'leafMesh' | 'leafTexture'>): void {
    if (update.leafTexture) this.setTexture(update.leafTexture);
    if (update.leafMesh) this.setLeafMesh(update.leafMesh);
    if (update.instances) this.setInstances(update.instances);
    else if (update.leafMesh) this.syncMesh(false);
  }

  private setInstances(instances: Instances): void {
    const count = instances.colors.length / 3;
    const mesh = this.mesh;
    this.instances = instances;
    if (mesh && count > 0 && mesh.count === count && mesh.geometry === this.geometry) {
      mesh.instanceMatrix.array = instances.matrices;
      mesh.instanceMatrix.needsUpdate = true;
      if (mesh.instanceColor) {
        mesh.instanceColor.array = instances.colors;
        mesh.instanceColor.needsUpdate = true;
      }
      return;
    }
    this.syncMesh(true);
  }

  /** Makes the instanced mesh draw the current leaf geometry and instances (`rebuild`: anew). */
  private syncMesh(rebuild: boolean): void {
    const instances = this.instances;
    const count = instances ? instances.colors.length / 3 : 0;
    if (!this.geometry || !instances || count === 0) {
      this.removeMesh();
      return;
    }
    if (this.mesh && !rebuild) {
      this.mesh.geometry = this.geometry;
      return;
    }
    this.removeMesh();
    const mesh = wrapInstances(
      this.geometry,
      this.material,
      instances.matrices,
      instances.colors,
      count,
    );
    // Bounds over every instance would loop over the leaves: the tree is framed by its bark.
    mesh.frustumCulled = false;
    if (this.depthMaterial) mesh.customDepthMaterial = this.depthMaterial;
    mesh.castShadow = true;
    mesh.receiveShadow = true;
    this.mesh = mesh;
    this.parent.add(mesh);
  }

  private setTexture(leafTexture: LeafTextureBuffers): void {
    this.texture?.dispose();
    const texture = makeLeafTexture(leafTexture);
    this.texture = texture;
    this.material.map = texture;
    this.material.emissiveMap = texture;
    this.material.needsUpdate = true;
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
    this.geometry?.dispose();
    this.geometry = leaf.indices.length > 0 ? geometry : null;
  }

  /** Releases the geometry, texture and material. */
  dispose(): void {
    this.removeMesh();
    this.geometry?.dispose();
    this.geometry = null;
    this.texture?.dispose();
    this.texture = null;
    this.material.dispose();
  }

  /** Removes the instanced mesh (its instance buffers go with it; the leaf geometry stays). */
  private removeMesh(): void {
    if (!this.mesh) return;
    this.parent.remove(this.mesh);
    this.mesh.dispose();
    this.mesh = null;
  }
}
