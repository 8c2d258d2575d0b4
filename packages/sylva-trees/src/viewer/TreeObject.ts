/**
 * One tree as three.js objects: a `Group` holding the bark mesh and the instanced leaves, with
 * the bark material (the core's baked maps and the bark look), the cut faces' end-grain material,
 * the leaf material (translucency) and the wind on all of them (and on their shadow depth
 * materials). It takes the worker's session
 * updates (only the arrays that changed): same-size arrays are swapped into the existing
 * attributes, other sizes get new geometry and the old one is disposed. No renderer, camera or
 * lights: the app's viewer and the `sylva-trees` package both put it into a scene of their own.
 */
import {
  DoubleSide,
  Group,
  Mesh,
  MeshStandardMaterial,
  Sphere,
  Vector3,
  type BufferGeometry,
  type InstancedMesh,
  type Texture,
} from 'three';
import type { BarkBuffers, TreeBuffers, TreeUpdate } from '../core/types';
import { BarkTextures, createBarkMaterial } from './barkMaterial';
import { createCutFaceMaterial, EndGrainTextures } from './cutFaceMaterial';
import { applyBarkLook, createBarkLookUniforms } from './barkLook';
import { Foliage } from './Foliage';
import { pickBark } from './barkPick';
import { buildTreeGeometry, updateShade, updateTreeGeometry } from './geometry';
import { applyLeafCoverage } from './leafCoverage';
import { applyLeafTranslucency } from './lighting';
import { applySoftShadows } from './softShadows';
import { OrganSets } from './organs';
import { mergeUpdate, updateOf } from './treeState';
import { WindController } from './wind';

const LEAF_COLOR = '#4c8a34';

/** Owns the meshes, materials, textures and wind of one tree. */
export class TreeObject {
  /** Add this to a scene: the bark mesh and the leaves are its children. */
  readonly group = new Group();
  /** Wind animation: uniforms, clock and settings shared by this tree's materials. */
  readonly wind: WindController;
  private readonly barkLook = createBarkLookUniforms();
  private readonly bark = createBarkMaterial();
  /** The bark mesh's second material slot (leaf index ranges; the core sends none today). */
  private readonly leaves = new MeshStandardMaterial({
    color: LEAF_COLOR,
    roughness: 0.75,
    side: DoubleSide,
  });
  /** The third slot: the end grain of cut stems' faces (`MATERIAL_INDEX.cut_face`). */
  private readonly cutFace = createCutFaceMaterial();
  private readonly endGrain = new EndGrainTextures(this.cutFace);
  private readonly foliage = new Foliage(this.group);
  private readonly barkTextures = new BarkTextures(this.bark, this.barkLook);
  /** Flowers, fruit, catkins and buds: swaying with the leaves, soft-shadowed as they are. */
  private readonly organs: OrganSets;
  private mesh: Mesh<BufferGeometry, MeshStandardMaterial[]> | null = null;
  /** The current bark's pick boxes (`core/pickBoxes.ts`), or null. */
  private pickBoxes: Float32Array | null = null;
  /** The whole current tree (session updates are merged into it). */
  private current: TreeBuffers | null = null;

  /** `onChange` is called when the wind needs a new frame. */
  constructor(onChange: () => void = () => undefined) {
    this.group.name = 'sylva-tree';
    this.wind = new WindController(onChange);
    this.wind.apply(this.bark, 'bark');
    this.wind.apply(this.leaves, 'bark');
    this.wind.apply(this.cutFace, 'bark');
    for (const leaves of [this.foliage.material, this.foliage.instancedMaterial]) {
      this.wind.apply(leaves, 'leaves');
      applyLeafTranslucency(leaves);
      applyLeafCoverage(leaves);
    }
    applyBarkLook(this.bark, this.barkLook);
    for (const material of [
      this.bark,
      this.leaves,
      this.cutFace,
      this.foliage.material,
      this.foliage.instancedMaterial,
    ]) {
      applySoftShadows(material);
    }
    this.foliage.setDepthMaterials(
      this.wind.depthMaterial('leaves', 'pulled'),
      this.wind.depthMaterial('leaves'),
    );
    this.organs = new OrganSets(this.group, {
      patch: (material) => {
        this.wind.apply(material, 'organs');
        applySoftShadows(material);
      },
      depthMaterial: () => this.wind.depthMaterial('organs'),
    });
  }

  /** The organ meshes drawn (one `InstancedMesh` per set). */
  get organMeshes(): readonly InstancedMesh[] {
    return this.organs.objects;
  }

  /** The whole current tree, null before the first update. */
  get buffers(): TreeBuffers | null {
    return this.current;
  }

  /** The bark mesh, null before the first tree. */
  get barkMesh(): Mesh<BufferGeometry, MeshStandardMaterial[]> | null {
    return this.mesh;
  }

  /** The leaf texture (null before the first leaves). */
  get leafMap(): Texture | null {
    return this.foliage.material.map;
  }

  /** Number of leaves drawn. */
  get leafCount(): number {
    return this.foliage.count;
  }

  /** Size of the bark colour map, null before the worker sent it. */
  get barkTexture(): { width: number; height: number } | null {
    return this.barkTextures.size;
  }

  /** The bark type of the cut faces' end grain, -1 before a tree with a cut arrived. */
  get endGrainKind(): number {
    return this.endGrain.kind;
  }

  /** The bark's bounding sphere (a unit sphere before the first tree). */
  get boundingSphere(): Sphere {
    return this.mesh?.geometry.boundingSphere ?? new Sphere(new Vector3(), 1);
  }

  /** Shows a whole new tree (every array given). */
  setTree(buffers: TreeBuffers): TreeBuffers {
    this.current = null;
    return this.apply(updateOf(buffers));
  }

  /** Applies a session update (only the arrays that changed); returns the whole current tree. */
  apply(update: TreeUpdate): TreeBuffers {
    const buffers = mergeUpdate(this.current, update);
    this.current = buffers;
    if (update.bark) this.setBark(update.bark, buffers);
    if (update.shade && this.mesh) updateShade(this.mesh.geometry, update.shade);
    this.foliage.update(update);
    if (update.organs) this.organs.set(update.organs);
    const geometry = this.mesh?.geometry;
    this.wind.setTree(buffers.meta.bounds, geometry?.hasAttribute('windPivot') ?? false);
    if (update.barkTextures) this.barkTextures.set(update.barkTextures);
    if (update.endGrain) this.endGrain.set(update.endGrain);
    return buffers;
  }

  /** The content hash of the current tree arrived (it follows the buffers). */
  setHash(hash: string): void {
    if (this.current) this.current.meta = { ...this.current.meta, hash };
  }

  private setBark(bark: BarkBuffers, buffers: TreeBuffers): void {
    this.pickBoxes = bark.pick ?? null;
    if (this.mesh && updateTreeGeometry(this.mesh.geometry, bark, buffers.meta)) return;
    const geometry = buildTreeGeometry(buffers);
    if (this.mesh) {
      this.mesh.geometry.dispose();
      this.mesh.geometry = geometry;
      return;
    }
    const mesh = new Mesh(geometry, [this.bark, this.leaves, this.cutFace]);
    // The tools pick on every pointer move: through the pick boxes, nearest hit only.
    mesh.raycast = (raycaster, hits) => pickBark(mesh, this.pickBoxes, raycaster, hits);
    this.mesh = mesh;
    this.mesh.name = 'sylva-bark';
    this.mesh.castShadow = true;
    this.mesh.receiveShadow = true;
    this.mesh.customDepthMaterial = this.wind.depthMaterial('bark');
    this.group.add(this.mesh);
  }

  /** Frees every geometry, material and texture and leaves the scene. */
  dispose(): void {
    this.group.removeFromParent();
    if (this.mesh) {
      this.group.remove(this.mesh);
      this.mesh.geometry.dispose();
      this.mesh = null;
    }
    this.foliage.dispose();
    this.organs.dispose();
    this.wind.dispose();
    this.barkTextures.dispose();
    this.endGrain.dispose();
    this.bark.dispose();
    this.leaves.dispose();
    this.cutFace.dispose();
    this.current = null;
  }
}
