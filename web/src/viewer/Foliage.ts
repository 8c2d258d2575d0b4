/**
 * The leaves of the tree: one `InstancedMesh` of the core's leaf geometry, with the instance
 * matrices and colours taken straight from the transferred typed arrays (no per-leaf loop on
 * the main thread) and a double-sided material that reads as thin leaf tissue: the baked leaf
 * texture with an alpha test, plus a dim emissive copy of it standing in for light shining
 * through the blade from behind.
 */
import type { InstancedMesh } from 'three';
import {
  BufferAttribute,
  BufferGeometry,
  DataTexture,
  DoubleSide,
  LinearFilter,
  LinearMipmapLinearFilter,
  MeshStandardMaterial,
  RGBAFormat,
  SRGBColorSpace,
  UnsignedByteType,
  type Material,
  type Object3D,
} from 'three';
import type { FoliageBuffers } from '../core/types';
import { wrapInstances } from './instances';

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
    if (!buffers) return;
    if (buffers.texture) {
      this.texture?.dispose();
      const { width, height, rgba } = buffers.texture;
      const texture = new DataTexture(rgba, width, height, RGBAFormat, UnsignedByteType);
      texture.colorSpace = SRGBColorSpace;
      texture.magFilter = LinearFilter;
      texture.minFilter = LinearMipmapLinearFilter;
      texture.generateMipmaps = true;
      texture.flipY = false;
      texture.needsUpdate = true;
      this.texture = texture;
      this.material.map = texture;
      this.material.emissiveMap = texture;
      this.material.needsUpdate = true;
    }
    const count = buffers.colors.length / 3;
    if (count === 0 || buffers.indices.length === 0) return;
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(buffers.positions, 3));
    geometry.setAttribute('normal', new BufferAttribute(buffers.normals, 3));
    geometry.setAttribute('uv', new BufferAttribute(buffers.uvs, 2));
    geometry.setIndex(new BufferAttribute(buffers.indices, 1));
    const mesh = wrapInstances(geometry, this.material, buffers.matrices, buffers.colors, count);
    // Bounds over every instance would loop over the leaves: the tree is framed by its bark.
    mesh.frustumCulled = false;
    if (this.depthMaterial) mesh.customDepthMaterial = this.depthMaterial;
    mesh.castShadow = true;
    mesh.receiveShadow = true;
    this.mesh = mesh;
    this.parent.add(mesh);
  }

  /** Releases the geometry, texture and material. */
  dispose(): void {
    this.removeMesh();
    this.texture?.dispose();
    this.texture = null;
    this.material.dispose();
  }

  private removeMesh(): void {
    if (!this.mesh) return;
    this.parent.remove(this.mesh);
    this.mesh.geometry.dispose();
    this.mesh.dispose();
    this.mesh = null;
  }
}
