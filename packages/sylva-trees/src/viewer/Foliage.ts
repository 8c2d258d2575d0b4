/**
 * The leaves of the tree: one draw of the core's leaf mesh per leaf, by vertex pulling
 * (`leafPull.ts`: the transferred matrices and tints go into float textures as they are, no
 * per-leaf loop on the main thread), with a double-sided material that reads as thin leaf
 * tissue: the baked leaf texture with an alpha test, plus a dim emissive copy of it standing in
 * for light shining through the blade from behind.
 */
import type { DataTexture } from 'three';
import { DoubleSide, Mesh, MeshStandardMaterial, type Material, type Object3D } from 'three';
import type {
  FoliageBuffers,
  LeafMeshBuffers,
  LeafTextureBuffers,
  TreeUpdate,
} from '../core/types';
import { applyLeafPull, LeafPullData } from './leafPull';
import { leafTexture as makeLeafTexture } from './leafTexture';

type Instances = NonNullable<TreeUpdate['instances']>;

/** Strength of the leaf's dim emissive copy of its texture (light shining through the blade). */
export const LEAF_TRANSLUCENCY = 0.22;

/** `userData` key of the leaf mesh: the matrices array it draws (LOD code finds it by it). */
export const LEAF_MATRICES_KEY = 'sylvaLeafMatrices';
/** `userData` key of the leaf mesh: the same look for an `InstancedMesh` of leaves. */
export const LEAF_INSTANCED_MATERIAL_KEY = 'sylvaInstancedLeafMaterial';

/** The leaf look: thin double-sided tissue, alpha-tested, lit through from behind. */
function leafMaterial(vertexColors: boolean): MeshStandardMaterial {
  return new MeshStandardMaterial({
    color: '#ffffff',
    roughness: 0.7,
    side: DoubleSide,
    alphaTest: 0.5,
    emissive: '#ffffff',
    emissiveIntensity: LEAF_TRANSLUCENCY,
    // Pulled leaves take their tints as vertex colours (see leafPull.ts).
    vertexColors,
  });
}

/** Owns the leaf textures, mesh and materials. */
export class Foliage {
  /** The leaf material (the viewer patches it with wind; it is made to pull its leaves). */
  readonly material = leafMaterial(true);
  /**
   * The same look for instanced leaves (`InstancedMesh`, tints from `instanceColor`): the
   * levels of detail draw theirs with it. The viewer patches it as it patches `material`.
   */
  readonly instancedMaterial = leafMaterial(false);
  private texture: DataTexture | null = null;
  private readonly data = new LeafPullData();
  private mesh: Mesh | null = null;
  private depth: Material | undefined = undefined;
  /** Whether the leaf material pulls its leaves yet (patched last, after the viewer's patches). */
  private pulled = false;

  constructor(private readonly parent: Object3D) {}

  /** Number of leaves shown. */
  get count(): number {
    return this.mesh ? this.data.count : 0;
  }

  /** Shadow depth material of the leaves (the wind's, so shadows move too); made to pull. */
  get depthMaterial(): Material | undefined {
    return this.depth;
  }

  set depthMaterial(material: Material | undefined) {
    if (material) applyLeafPull(material, this.data.uniforms);
    this.depth = material;
    if (this.mesh) this.mesh.customDepthMaterial = material;
  }

  /** Replaces the leaves (an empty buffer set removes them). */
  set(buffers: FoliageBuffers | undefined): void {
    this.update({
      instances: buffers
        ? { matrices: buffers.matrices, colors: buffers.colors }
        : { matrices: new Float32Array(0), colors: new Float32Array(0) },
      ...(buffers ? { leafMesh: buffers } : {}),
      ...(buffers?.texture ? { leafTexture: buffers.texture } : {}),
    });
  }

  /**
   * Applies the leaf parts of a session update; absent parts stay. The arrays are copied into
   * the leaf textures, which keep their GPU storage while their number of rows stays the same.
   */
  update(update: Pick<TreeUpdate, 'instances' | 'leafMesh' | 'leafTexture'>): void {
    if (update.leafTexture) this.setTexture(update.leafTexture);
    if (update.leafMesh) this.setLeafMesh(update.leafMesh);
    if (update.instances) this.setInstances(update.instances);
    this.syncMesh(update.instances?.matrices);
  }

  private setInstances(instances: Instances): void {
    this.data.setInstances(instances.matrices, instances.colors);
  }

  private setLeafMesh(leaf: LeafMeshBuffers): void {
    this.data.setMesh(leaf);
  }

  /** Adds the leaf mesh when there is something to draw, removes it when not. */
  private syncMesh(matrices: Float32Array | undefined): void {
    if (this.data.vertexCount === 0) {
      this.removeMesh();
      return;
    }
    if (!this.pulled) {
      applyLeafPull(this.material, this.data.uniforms);
      this.pulled = true;
    }
    if (!this.mesh) {
      const mesh = new Mesh(this.data.geometry, this.material);
      mesh.name = 'sylva-leaves';
      // The geometry has no positions to bound: the tree is framed by its bark.
      mesh.frustumCulled = false;
      if (this.depth) mesh.customDepthMaterial = this.depth;
      mesh.castShadow = true;
      mesh.receiveShadow = true;
      this.mesh = mesh;
      this.parent.add(mesh);
    }
    if (matrices) this.mesh.userData[LEAF_MATRICES_KEY] = matrices;
    this.mesh.userData[LEAF_INSTANCED_MATERIAL_KEY] = this.instancedMaterial;
  }

  private setTexture(leafTexture: LeafTextureBuffers): void {
    this.texture?.dispose();
    const texture = makeLeafTexture(leafTexture);
    this.texture = texture;
    for (const material of [this.material, this.instancedMaterial]) {
      material.map = texture;
      material.emissiveMap = texture;
      material.needsUpdate = true;
    }
  }

  /** Releases the textures, geometry and material. */
  dispose(): void {
    this.removeMesh();
    this.data.dispose();
    this.texture?.dispose();
    this.texture = null;
    this.material.dispose();
    this.instancedMaterial.dispose();
  }

  /** Removes the leaf mesh (the leaf textures stay for the next leaves). */
  private removeMesh(): void {
    if (!this.mesh) return;
    this.parent.remove(this.mesh);
    this.mesh = null;
  }
}
