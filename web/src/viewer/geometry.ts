/** Builds a three.js BufferGeometry straight from the worker's transferred typed arrays. */
import { Box3, BufferAttribute, BufferGeometry, Sphere, Vector3 } from 'three';
import type { TreeBuffers } from '../core/types';
import { attachBarkAttributes } from './barkLook';
import { attachWindAttributes } from './wind';

/** Material slot of each mesh group in the material array [bark, leaves]. */
export const MATERIAL_INDEX = { bark: 0, leaves: 1 } as const;

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
  for (const group of tree.meta.groups) {
    geometry.addGroup(group.start, group.count, MATERIAL_INDEX[group.material]);
  }
  const { min, max } = tree.meta.bounds;
  geometry.boundingBox = new Box3(new Vector3(...min), new Vector3(...max));
  geometry.boundingSphere = geometry.boundingBox.getBoundingSphere(new Sphere());
  return geometry;
}

/** Wraps the core's envelope line segments (x, y, z pairs) for a LineSegments object. */
export function buildEnvelopeGeometry(lines: Float32Array): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(lines, 3));
  return geometry;
}
