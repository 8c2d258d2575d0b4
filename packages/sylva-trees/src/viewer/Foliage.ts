/**
 * The leaves of the tree: the core's leaf mesh once per leaf, with a double-sided material that
 * reads as thin leaf tissue (the baked leaf texture with an alpha test, plus a dim emissive copy
 * of it standing in for light shining through the blade from behind). Small leaf meshes (leaf
 * cards, simple blades: at most [`PULL_MAX_INDICES`] indices) are drawn by vertex pulling, one
 * plain draw (`leafPull.ts`); bigger ones as an `InstancedMesh` (`instancedLeaves.ts`). Software
 * WebGL runs every instance of an instanced draw as a draw of its own (about 12 µs each in
 * SwiftShader), while a pulled leaf costs every one of its indices a vertex of its own (about
 * 0.7 µs each, no vertex reuse): pulling is 3× faster for the default tree's two-triangle
 * leaves, and would be slower than instancing for CA Black Oak's 25-triangle lobed ones. Either
 * way the transferred arrays are used as they are, with no per-leaf loop on the main thread.
 */
import type { DataTexture, InstancedMesh } from 'three';
import { DoubleSide, Mesh, MeshStandardMaterial, type Material, type Object3D } from 'three';
import type {
  FoliageBuffers,
  LeafMeshBuffers,
  LeafTextureBuffers,
  TreeUpdate,
} from '../core/types';
import { InstancedLeaves, type LeafInstances } from './instancedLeaves';
import { applyLeafPull, LeafPullData } from './leafPull';
import { leafTexture as makeLeafTexture } from './leafTexture';

/** Leaf meshes with at most this many indices (8 triangles) are pulled, bigger ones instanced. */
export const PULL_MAX_INDICES = 24;

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
  /** The leaf material of pulled leaves (the viewer patches it with wind; it is made to pull). */
  readonly material = leafMaterial(true);
  /**
   * The same look for instanced leaves (`InstancedMesh`, tints from `instanceColor`): big leaf
   * meshes and the levels of detail draw with it. The viewer patches it as it patches `material`.
   */
  readonly instancedMaterial = leafMaterial(false);
  private texture: DataTexture | null = null;
  private readonly data = new LeafPullData();
  private readonly instanced: InstancedLeaves;
  private pulledMesh: Mesh | null = null;
  private depth: { pulled?: Material; instanced?: Material } = {};
  /** Whether the leaf material pulls its leaves yet (patched last, after the viewer's patches). */
  private pulled = false;
  private leaf: LeafMeshBuffers | null = null;
  private instances: LeafInstances | null = null;

  constructor(private readonly parent: Object3D) {
    this.instanced = new InstancedLeaves(
      parent,
      this.instancedMaterial,
      () => this.depth.instanced,
    );
  }

  /** Number of leaves shown. */
  get count(): number {
    return this.object && this.instances ? this.instances.colors.length / 3 : 0;
  }

  /** The object drawing the leaves (null: none). */
  get object(): Mesh | InstancedMesh | null {
    return this.pulledMesh ?? this.instanced.object;
  }

  /**
   * Shadow depth materials of the leaves (the wind's, so shadows move too): one for pulled
   * leaves (made to pull here) and one for instanced leaves.
   */
  setDepthMaterials(pulled: Material, instanced: Material): void {
    applyLeafPull(pulled, this.data.uniforms);
    this.depth = { pulled, instanced };
    if (this.pulledMesh) this.pulledMesh.customDepthMaterial = pulled;
    const object = this.instanced.object;
    if (object) object.customDepthMaterial = instanced;
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
   * Applies the leaf parts of a session update; absent parts stay. Pulled leaves are copied into
   * their textures (which keep their GPU storage while their rows stay the same); instanced ones
   * are swapped into the instance buffers when the sizes allow.
   */
  update(update: Pick<TreeUpdate, 'instances' | 'leafMesh' | 'leafTexture'>): void {
    if (update.leafTexture) this.setTexture(update.leafTexture);
    if (update.leafMesh) this.leaf = update.leafMesh;
    if (update.instances) this.instances = update.instances;
    const leaf = this.leaf;
    const instances = this.instances;
    if (!leaf || !instances || instances.colors.length === 0 || leaf.indices.length === 0) {
      this.removePulled();
      this.instanced.remove();
      return;
    }
    if (leaf.indices.length <= PULL_MAX_INDICES) {
      this.instanced.remove();
      const fresh = !this.pulledMesh;
      if (update.leafMesh || fresh) this.data.setMesh(leaf);
      if (update.instances || fresh) this.data.setInstances(instances.matrices, instances.colors);
      this.showPulled(instances.matrices);
    } else {
      this.removePulled();
      this.instanced.show(leaf, update.leafMesh !== undefined, instances);
    }
  }

  /** Adds the pulled leaf mesh if it is not in the scene yet. */
  private showPulled(matrices: Float32Array): void {
    if (!this.pulled) {
      applyLeafPull(this.material, this.data.uniforms);
      this.pulled = true;
    }
    if (!this.pulledMesh) {
      const mesh = new Mesh(this.data.geometry, this.material);
      mesh.name = 'sylva-leaves';
      // The geometry has no positions to bound: the tree is framed by its bark.
      mesh.frustumCulled = false;
      if (this.depth.pulled) mesh.customDepthMaterial = this.depth.pulled;
      mesh.castShadow = true;
      mesh.receiveShadow = true;
      mesh.userData[LEAF_INSTANCED_MATERIAL_KEY] = this.instancedMaterial;
      this.pulledMesh = mesh;
      this.parent.add(mesh);
    }
    this.pulledMesh.userData[LEAF_MATRICES_KEY] = matrices;
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

  /** Releases the textures, geometry and materials. */
  dispose(): void {
    this.removePulled();
    this.instanced.dispose();
    this.data.dispose();
    this.texture?.dispose();
    this.texture = null;
    this.material.dispose();
    this.instancedMaterial.dispose();
  }

  /**
   * Removes the pulled leaf mesh and releases its textures (a few MB for the default tree): the
   * next pulled leaves fill new ones.
   */
  private removePulled(): void {
    if (!this.pulledMesh) return;
    this.parent.remove(this.pulledMesh);
    this.pulledMesh = null;
    this.data.release();
  }
}
