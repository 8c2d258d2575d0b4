/**
 * Builds a three.js BufferGeometry straight from the worker's transferred typed arrays, and
 * updates one in place when a new tree has the same sizes (the arrays are swapped into the
 * existing attributes: no new GPU buffers, the upload is a `bufferSubData`).
 */
import type { InterleavedBufferAttribute } from 'three';
import { Box3, BufferAttribute, BufferGeometry, Sphere, Vector3, type TypedArray } from 'three';
import type { BarkBuffers, TreeBuffers, TreeMeta } from '../core/types';
import { attachBarkAttributes, shadeBytes } from './barkLook';
import { attachWindAttributes } from './wind';

/**
 * Material slot of each mesh group in the material array [bark, leaves, cut face]: a cut stem's
 * face (`cut_face`) draws with the end-grain material (cutFaceMaterial.ts) in its disc uvs. The
 * bark mesh never carries `organ` groups (organ sets are meshes of their own, organs.ts); the
 * slot of the leaves stands in, as in the core's GLB.
 */
export const MATERIAL_INDEX = { bark: 0, leaves: 1, cut_face: 2, organ: 1 } as const;

/** Wraps the arrays in BufferAttributes (no copying, no per-vertex JS) and adds material groups. */
export function buildTreeGeometry(tree: TreeBuffers): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(tree.positions, 3));
  geometry.setAttribute('normal', new BufferAttribute(tree.normals, 3));
  geometry.setAttribute('uv', new BufferAttribute(tree.uvs, 2));
  geometry.setIndex(new BufferAttribute(tree.indices, 1));
  // The core's wind data as `windPivot` + `windParams` (wrapped, not copied), when it has any.
  attachWindAttributes(geometry, tree.wind);
  // The bark look's stem radius (a view of the wind data) and occlusion.
  attachBarkAttributes(geometry, tree.shade);
  setGroupsAndBounds(geometry, tree.meta);
  return geometry;
}

function setGroupsAndBounds(geometry: BufferGeometry, meta: TreeMeta): void {
  geometry.clearGroups();
  for (const group of meta.groups) {
    geometry.addGroup(group.start, group.count, MATERIAL_INDEX[group.material]);
  }
  const { min, max } = meta.bounds;
  geometry.boundingBox = new Box3(new Vector3(...min), new Vector3(...max));
  geometry.boundingSphere = geometry.boundingBox.getBoundingSphere(new Sphere());
}

/** Whether `array` can replace the contents of `attribute` without a new GPU buffer. */
function fits(attribute: { array: TypedArray } | null | undefined, array: TypedArray): boolean {
  return (
    attribute !== null &&
    attribute !== undefined &&
    attribute.array.length === array.length &&
    attribute.array.constructor === array.constructor
  );
}

/** Swaps `array` into `attribute` and marks it for upload. */
function swap(attribute: { array: TypedArray; needsUpdate: boolean }, array: TypedArray): void {
  attribute.array = array;
  attribute.needsUpdate = true;
}

/**
 * Puts `bark` into `geometry` in place when every array has the size of the one it replaces
 * (wind present in both or in neither); returns false, changing nothing, otherwise.
 */
export function updateTreeGeometry(
  geometry: BufferGeometry,
  bark: BarkBuffers,
  meta: TreeMeta,
): boolean {
  const position = geometry.getAttribute('position') as BufferAttribute | undefined;
  const normal = geometry.getAttribute('normal') as BufferAttribute | undefined;
  const uv = geometry.getAttribute('uv') as BufferAttribute | undefined;
  const index = geometry.getIndex();
  const windAttr = geometry.getAttribute('windPivot') as InterleavedBufferAttribute | undefined;
  const wind = windAttr?.data;
  const windFits = wind ? fits(wind, bark.wind) : bark.wind.length === 0;
  if (
    !position ||
    !normal ||
    !uv ||
    !fits(position, bark.positions) ||
    !fits(normal, bark.normals) ||
    !fits(uv, bark.uvs) ||
    !fits(index, bark.indices) ||
    !windFits
  ) {
    return false;
  }
  swap(position, bark.positions);
  swap(normal, bark.normals);
  swap(uv, bark.uvs);
  if (index) swap(index, bark.indices);
  // The bark look's radius attribute is a view of the same wind buffer: it follows.
  if (wind) swap(wind, bark.wind);
  setGroupsAndBounds(geometry, meta);
  return true;
}

/**
 * Puts a new bark occlusion into `geometry`'s `barkShade` attribute in place (one byte per
 * vertex; empty or the wrong size means open sky everywhere).
 */
export function updateShade(geometry: BufferGeometry, shade: Uint8Array): void {
  const attribute = geometry.getAttribute('barkShade') as BufferAttribute | undefined;
  const bytes = shadeBytes(shade, geometry.getAttribute('position').count);
  if (attribute && fits(attribute, bytes)) swap(attribute, bytes);
  else geometry.setAttribute('barkShade', new BufferAttribute(bytes, 1, true));
}

/** Wraps the core's envelope line segments (x, y, z pairs) for a LineSegments object. */
export function buildEnvelopeGeometry(lines: Float32Array): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(lines, 3));
  return geometry;
}
