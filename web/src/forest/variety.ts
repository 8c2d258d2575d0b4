/**
 * One variety of the forest (ForestScene.ts): a unique tree's levels of detail as three.js
 * geometry and materials (bark, baked leaves, the billboard cloud with the clump atlas made in
 * the worker) and its impostor, baked from LOD2.
 */
import { applyLeafCoverage, impostorLights, leafTexture } from 'sylva-trees/viewer';
import type { LodBuffers } from 'sylva-trees/worker';
import {
  DoubleSide,
  MeshStandardMaterial,
  type BufferGeometry,
  type Material,
  type Sphere,
  type WebGLRenderer,
} from 'three';
import {
  bakeImpostor,
  impostorGeometry,
  impostorMaterial,
  type ImpostorAtlas,
} from '../lod/impostor';
import {
  BARK_COLOR,
  bakedLeafGeometry,
  barkGeometry,
  cloudGeometry,
  cloudMaterial,
  clumpTexture,
  treeBox,
  treeSphere,
} from '../lod/lodObjects';
import type { PlacedTree } from './ecology';

/**
 * Views per side of a forest impostor's atlas (6 × 6 = 36, a view every 30° or so; the tree
 * viewer's impostor has 8 × 8): the bake's cost is per view (4-5 ms each in software WebGL), and
 * the depth-aware blend between neighbouring views hides the wider steps at a forest's
 * distances.
 */
const IMPOSTOR_FRAMES = 6;

/** One variety's geometry, materials and impostor (shared by all its instances). */
export interface Variety {
  sphere: Sphere;
  /** The unique tree it is (`ecology.ts`): its index, species and crown radius (m). */
  tree: PlacedTree;
  /** Per level 0..3: the parts (geometry + material) drawn for each instance. */
  parts: { geometry: BufferGeometry; material: Material }[][];
  atlas: ImpostorAtlas;
  disposables: { dispose(): void }[];
  triangles: number[];
}

/**
 * Unique tree `tree` (`id` and `species` as `uniqueTrees` made it) as a variety of the forest:
 * its levels' geometry and materials, and its impostor baked with `renderer`.
 */
export function buildVariety(
  lods: LodBuffers,
  tree: { id: number; species: number },
  renderer: WebGLRenderer,
): Variety {
  const sphere = treeSphere(lods);
  const { min, max } = treeBox(lods);
  const crown = Math.max(max.x - min.x, max.z - min.z) / 2;
  const disposables: { dispose(): void }[] = [];
  const own = <T extends { dispose(): void }>(x: T): T => {
    disposables.push(x);
    return x;
  };
  const map = lods.leafTexture ? own(leafTexture(lods.leafTexture)) : null;
  const bark = own(new MeshStandardMaterial({ color: BARK_COLOR, roughness: 0.92 }));
  const leaves = own(
    new MeshStandardMaterial({
      color: '#ffffff',
      map,
      vertexColors: true,
      alphaTest: 0.5,
      side: DoubleSide,
      roughness: 0.7,
    }),
  );
  applyLeafCoverage(leaves);
  const parts: Variety['parts'] = [];
  // One clump atlas (made in the worker) for the clouds of every level.
  const clump = lods.clump ? own(cloudMaterial(own(clumpTexture(lods.clump)))) : null;
  for (let l = 0; l < 3; l++) {
    const level = lods.levels[l]!;
    const list = [{ geometry: own(barkGeometry(level)), material: bark as Material }];
    const merged = bakedLeafGeometry(level);
    if (merged) list.push({ geometry: own(merged), material: leaves });
    const cloud = cloudGeometry(level);
    if (cloud && clump) list.push({ geometry: own(cloud), material: clump });
    parts.push(list);
  }
  // The impostor is baked from LOD2 here (LOD0 in the tree viewer), the level it takes over
  // from: the far trees keep LOD2's look, and the bake draws 64 views of a few thousand
  // triangles (from LOD1: about 90,000, 2 s a tree in software WebGL against 0.3).
  const source = parts[2]!.map((p) => ({
    geometry: p.geometry,
    color: p.material === bark ? BARK_COLOR : '#ffffff',
    map: p.material === bark ? null : (p.material as MeshStandardMaterial).map,
    vertexColors: p.material !== bark,
    doubleSided: p.material !== bark,
  }));
  // Single-sampled: the forest's instanced impostors are alpha-tested, not blended by coverage.
  const atlas = own(
    bakeImpostor(renderer, source, sphere, { frames: IMPOSTOR_FRAMES, cellPx: 64, samples: 0 }),
  );
  // The scene's own lights (lighting.ts), as the near trees have them.
  const imp = own(impostorMaterial(atlas, impostorLights()));
  parts.push([{ geometry: own(impostorGeometry()), material: imp }]);
  const t = lods.meta.levels.map((x) => x.triangles);
  return {
    sphere,
    tree: { ...tree, crown },
    parts,
    atlas,
    disposables,
    triangles: [...t, 2],
  };
}
