/**
 * three.js objects for one level of detail: bark tubes, instanced leaves, and the billboard
 * cloud (LOD2) as textured quads. The cloud texture is a "leaf clump" rasterised in the worker from
 * the tree's own leaf texture (`clumpAtlas`: leaves scattered in a disc), tinted per quad with the
 * cluster's mean leaf colour, and lit like the leaves (the same translucency), so LOD2 keeps
 * LOD0's colour: its transparent texels carry the clump's mean colour, not black, so the mipmaps
 * a distant cloud samples do not darken toward the leaves' edges.
 */
import type { InstancedMesh } from 'three';
import {
  BufferAttribute,
  BufferGeometry,
  Color,
  FrontSide,
  Mesh,
  MeshStandardMaterial,
  Sphere,
  Vector3,
  type Material,
  type Texture,
} from 'three';
import type { MeshGroup } from 'sylva-trees/core';
import {
  attachBarkAttributes,
  LEAF_TRANSLUCENCY,
  MATERIAL_INDEX,
  srgbTexture,
  wrapInstances,
} from 'sylva-trees/viewer';
import {
  type ClumpBuffers,
  densityCell,
  type LodBuffers,
  type LodLevelBuffers,
  QUAD_FLOATS,
} from 'sylva-trees/worker';

/** Bark colour of the viewer (TreeViewer's flat bark). */
export const BARK_COLOR = '#5b3d26';

/** The bark tubes of a level. */
export function barkGeometry(level: LodLevelBuffers): BufferGeometry {
  const g = new BufferGeometry();
  g.setAttribute('position', new BufferAttribute(level.positions, 3));
  g.setAttribute('normal', new BufferAttribute(level.normals, 3));
  g.setAttribute('uv', new BufferAttribute(level.uvs, 2));
  g.setIndex(new BufferAttribute(level.indices, 1));
  // The viewer's bark material reads the occlusion and radius attributes: without them the
  // shader reads 0 (a black bark).
  attachBarkAttributes(g, level.shade);
  g.computeBoundingSphere();
  return g;
}

/** The leaf mesh (leaf units) of a level, or null when it has no leaves. */
export function leafGeometry(level: LodLevelBuffers): BufferGeometry | null {
  if (level.leafIndices.length === 0 || level.leafColors.length === 0) return null;
  const g = new BufferGeometry();
  g.setAttribute('position', new BufferAttribute(level.leafPositions, 3));
  g.setAttribute('normal', new BufferAttribute(level.leafNormals, 3));
  g.setAttribute('uv', new BufferAttribute(level.leafUvs, 2));
  g.setIndex(new BufferAttribute(level.leafIndices, 1));
  return g;
}

/** The leaves of a level as one InstancedMesh (matrices and colours wrap the transferred arrays). */
export function leafMesh(level: LodLevelBuffers, material: Material): InstancedMesh | null {
  const geometry = leafGeometry(level);
  if (!geometry) return null;
  const count = level.leafColors.length / 3;
  const mesh = wrapInstances(geometry, material, level.leafMatrices, level.leafColors, count);
  mesh.frustumCulled = false;
  return mesh;
}

/**
 * A level's leaves as one geometry (what the forest instances per tree, since three.js cannot
 * instance an instanced mesh): the buffers the pool worker baked with the core's exporter
 * (a pool `lods` job with `bakeLeaves`), wrapped as they are, the tint as a vertex colour; null when
 * the level has none.
 */
export function bakedLeafGeometry(level: LodLevelBuffers): BufferGeometry | null {
  const baked = level.bakedLeaves;
  if (!baked || baked.indices.length === 0) return null;
  return coloredGeometry(baked.positions, baked.normals, baked.uvs, baked.colors, baked.indices);
}

/**
 * The billboard cloud as quads: 4 vertices each (corners `c ± u ± v`), both windings, the cluster tint as a
 * vertex colour, and normals facing up like the leaves' fronts, leaning `CLOUD_OUTWARD` away from
 * the crown centre (a rounded crown under light, lit as brightly as the leaves it stands for).
 */
export function cloudGeometry(level: LodLevelBuffers): BufferGeometry | null {
  const q = level.cloud;
  const n = q.length / QUAD_FLOATS;
  if (n === 0) return null;
  const positions = new Float32Array(n * 12);
  const normals = new Float32Array(n * 12);
  const uvs = new Float32Array(n * 8);
  const colors = new Float32Array(n * 12);
  const indices = new Uint32Array(n * 12);
  let cx = 0;
  let cy = 0;
  let cz = 0;
  for (let k = 0; k < n; k++) {
    cx += q[k * QUAD_FLOATS]! / n;
    cy += q[k * QUAD_FLOATS + 1]! / n;
    cz += q[k * QUAD_FLOATS + 2]! / n;
  }
  const corners = [
    [-1, -1],
    [1, -1],
    [1, 1],
    [-1, 1],
  ] as const;
  for (let k = 0; k < n; k++) {
    const o = k * QUAD_FLOATS;
    const c = [q[o]!, q[o + 1]!, q[o + 2]!];
    const cell = densityCell((q[o + 12] ?? 1) * CLOUD_DENSITY_GAIN);
    // Mostly up, like the leaves (whose fronts turn to the sky), leaning a little outward so
    // the crown still reads round (CLOUD_UP: measured in e2e lodBrightness.spec.ts).
    const out = Math.hypot(c[0]! - cx, c[1]! - cy, c[2]! - cz) || 1;
    let nx = (c[0]! - cx) / out;
    let ny = CLOUD_UP + (c[1]! - cy) / out;
    let nz = (c[2]! - cz) / out;
    const len = Math.hypot(nx, ny, nz);
    [nx, ny, nz] = [nx / len, ny / len, nz / len];
    corners.forEach(([su, sv], j) => {
      const p = (k * 4 + j) * 3;
      for (let a = 0; a < 3; a++) {
        positions[p + a] = c[a]! + CLOUD_GROW * (su * q[o + 3 + a]! + sv * q[o + 6 + a]!);
        colors[p + a] = q[o + 9 + a]! * CLOUD_TINT_GAIN;
      }
      normals[p] = nx;
      normals[p + 1] = ny;
      normals[p + 2] = nz;
      // The clump texture is a 2×2 atlas of densities (CELL_DENSITY): the quad shows the nearest.
      uvs[(k * 4 + j) * 2] = (cell % 2) * 0.5 + (su + 1) / 4;
      uvs[(k * 4 + j) * 2 + 1] = Math.floor(cell / 2) * 0.5 + (sv + 1) / 4;
    });
    // Both windings over the same vertices: whichever side faces the camera keeps the up-facing
    // normal (a double-sided material would flip it on the back and darken the cloud).
    const [i0, i1, i2, i3] = [k * 4, k * 4 + 1, k * 4 + 2, k * 4 + 3];
    indices.set([i0, i1, i2, i0, i2, i3, i0, i2, i1, i0, i3, i2], k * 12);
  }
  return coloredGeometry(positions, normals, uvs, colors, indices);
}

/** Upward bias of the cloud normals, added to the unit vector out from the crown centre. */
const CLOUD_UP = 4;
/**
 * Gain on the cluster tints. LOD0 brightens by about 10% from up close to a middle distance (the
 * sky shows through its sub-pixel leaves), the blended cloud by about 5%; without the gain the
 * cloud was 0.988 of LOD0 up close and 0.934 at the middle distance. With it: 1.028 and 0.971,
 * both within the 5% target (e2e lodBrightness.spec.ts, the default tree).
 */
const CLOUD_TINT_GAIN = 1.14;
/** Gain on a quad's leaf density before picking its atlas cell (overlapping cards hide the sky as the crown does). */
const CLOUD_DENSITY_GAIN = 2;
/**
 * Growth of every quad about its centre: the cloud then covers as many pixels as LOD0's crown
 * (41,688 against 41,737 for the default tree up close; the quads as built covered 84%, and the
 * sky through the missing 16% made LOD2 68-79% brighter than LOD0, e2e lodBrightness.spec.ts).
 */
const CLOUD_GROW = 1.3;

/** A geometry of positions, normals, uvs and vertex colours, indexed, with its bounds. */
function coloredGeometry(
  positions: Float32Array,
  normals: Float32Array,
  uvs: Float32Array,
  colors: Float32Array,
  indices: Uint32Array,
): BufferGeometry {
  const g = new BufferGeometry();
  g.setAttribute('position', new BufferAttribute(positions, 3));
  g.setAttribute('normal', new BufferAttribute(normals, 3));
  g.setAttribute('uv', new BufferAttribute(uvs, 2));
  g.setAttribute('color', new BufferAttribute(colors, 3));
  g.setIndex(new BufferAttribute(indices, 1));
  g.computeBoundingSphere();
  return g;
}

/** The billboard cloud's clump atlas (made in the worker, `LodBuffers.clump`) as a texture. */
export function clumpTexture(clump: ClumpBuffers): Texture {
  return srgbTexture(clump.rgba, clump.size, clump.size);
}

/**
 * Material of the billboard cloud (clump texture × quad tint, alpha-tested; the quads carry both
 * windings, see `cloudGeometry`), lit like
 * the leaves' own material (viewer/Foliage.ts: roughness and the emissive translucency).
 */
export function cloudMaterial(map: Texture): MeshStandardMaterial {
  return new MeshStandardMaterial({
    map,
    vertexColors: true,
    // Blended by the clump's coverage, as LOD0's sub-pixel leaves blend with the sky behind them
    // (an alpha test alone drew every clump solid: 14% darker than LOD0 from the same camera).
    alphaTest: 0.15,
    transparent: true,
    // Unsorted quads of one mesh: a card drawn first would hide the cards behind it through its
    // half-transparent texels (the sky showed through the crown in white fringes).
    depthWrite: false,
    side: FrontSide,
    roughness: 0.7,
    emissive: '#ffffff',
    emissiveMap: map,
    emissiveIntensity: LEAF_TRANSLUCENCY,
  });
}

/** Bounding sphere of a whole tree: bark bounds plus every leaf (position ± its length). */
export function treeSphere(lods: LodBuffers): Sphere {
  const { min, max } = treeBox(lods);
  return new Sphere(min.clone().add(max).multiplyScalar(0.5), max.distanceTo(min) / 2);
}

/** The tree's box: LOD0's bark bounds grown by every leaf (position ± length). */
export function treeBox(lods: LodBuffers): { min: Vector3; max: Vector3 } {
  const { min, max } = lods.meta.bounds;
  const lo = new Vector3(...min);
  const hi = new Vector3(...max);
  const m = lods.levels[0]?.leafMatrices ?? new Float32Array(0);
  for (let o = 0; o + 16 <= m.length; o += 16) {
    const len = Math.hypot(m[o + 4]!, m[o + 5]!, m[o + 6]!);
    lo.min(new Vector3(m[o + 12]! - len, m[o + 13]! - len, m[o + 14]! - len));
    hi.max(new Vector3(m[o + 12]! + len, m[o + 13]! + len, m[o + 14]! + len));
  }
  return { min: lo, max: hi };
}

/** A colour from a CSS string (linear working space). */
export function color(css: string): Color {
  return new Color(css);
}

/**
 * Bark mesh of a level. With the viewer's material array ([bark, leaves, cut face]) the level's
 * `groups` pick each range's material as LOD0's do (`MATERIAL_INDEX`: a cut stem's face shows its
 * end grain); with one material, a shorter array or no groups, the whole mesh draws with the (first) one.
 */
export function barkMesh(
  level: LodLevelBuffers,
  material: Material | Material[],
  groups: readonly MeshGroup[] = [],
): Mesh {
  const geometry = barkGeometry(level);
  if (!Array.isArray(material)) return new Mesh(geometry, material);
  const slots = Math.max(...Object.values(MATERIAL_INDEX)) + 1;
  if (groups.length === 0 || material.length < slots) return new Mesh(geometry, material[0]);
  for (const g of groups) geometry.addGroup(g.start, g.count, MATERIAL_INDEX[g.material]);
  return new Mesh(geometry, material);
}
