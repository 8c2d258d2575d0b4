/**
 * The tree's flowers, fruit, catkins and buds: one `InstancedMesh` per organ set of the core
 * (`OrganSetBuffers`), its part's geometry drawn once per instance through the transferred
 * matrices, tinted per instance (`instanceColor`) in a plain `MeshStandardMaterial` of the set's
 * colour (sRGB) and roughness, double-sided (petals and samara wings are single blades). The
 * arrays are used as they came (no per-instance loop on the main thread). A new list of sets
 * replaces the old: their geometries and materials are disposed. Organs are not picked (the
 * tools pick the bark) and are framed by the bark, like the leaves.
 */
import {
  BufferAttribute,
  BufferGeometry,
  Color,
  DoubleSide,
  MeshStandardMaterial,
  SRGBColorSpace,
  type InstancedMesh,
  type Material,
  type Object3D,
} from 'three';
import type { OrganSetBuffers } from '../core/types';
import { wrapInstances } from './instances';

/** Name prefix of the organ meshes (`sylva-organs:acorns`): tests and tools find them by it. */
export const ORGAN_MESH_PREFIX = 'sylva-organs:';

/** What the tree does to each organ material it makes (wind, soft shadows) and their depth material. */
export interface OrganLook {
  patch(material: MeshStandardMaterial): void;
  depthMaterial(): Material | undefined;
}

/** The material of one set: its sRGB colour, roughness, two-sided, tinted per instance. */
export function organMaterial(set: OrganSetBuffers): MeshStandardMaterial {
  const [r, g, b] = set.color;
  return new MeshStandardMaterial({
    color: new Color().setRGB(r, g, b, SRGBColorSpace),
    roughness: set.roughness,
    metalness: 0,
    side: DoubleSide,
  });
}

/** The part's geometry (positions, normals, triangle list), wrapping the given arrays. */
export function organGeometry(set: OrganSetBuffers): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(set.positions, 3));
  geometry.setAttribute('normal', new BufferAttribute(set.normals, 3));
  geometry.setIndex(new BufferAttribute(set.indices, 1));
  return geometry;
}

/** Owns the organ meshes of one tree. */
export class OrganSets {
  private meshes: InstancedMesh[] = [];

  constructor(
    private readonly parent: Object3D,
    private readonly look: OrganLook = { patch: () => undefined, depthMaterial: () => undefined },
  ) {}

  /** The meshes drawn, one per set with instances. */
  get objects(): readonly InstancedMesh[] {
    return this.meshes;
  }

  /** Replaces the sets drawn by `sets` (an empty list removes them all). */
  set(sets: readonly OrganSetBuffers[]): void {
    this.clear();
    for (const set of sets) {
      const count = set.colors.length / 3;
      if (count === 0 || set.indices.length === 0) continue;
      const material = organMaterial(set);
      this.look.patch(material);
      const mesh = wrapInstances(organGeometry(set), material, set.matrices, set.colors, count);
      mesh.name = `${ORGAN_MESH_PREFIX}${set.name}`;
      mesh.userData.organKind = set.kind;
      // Framed by the bark (bounds over every instance would loop over them); never picked.
      mesh.frustumCulled = false;
      mesh.raycast = () => undefined;
      mesh.castShadow = true;
      mesh.receiveShadow = true;
      const depth = this.look.depthMaterial();
      if (depth) mesh.customDepthMaterial = depth;
      this.meshes.push(mesh);
      this.parent.add(mesh);
    }
  }

  /** Removes every set and frees its geometry, material and instance buffers. */
  clear(): void {
    for (const mesh of this.meshes) {
      this.parent.remove(mesh);
      mesh.geometry.dispose();
      (mesh.material as Material).dispose();
      mesh.dispose();
    }
    this.meshes = [];
  }

  /** Same as [`OrganSets.clear`]. */
  dispose(): void {
    this.clear();
  }
}
