/**
 * What the LOD controller finds of the viewer's own tree (LOD0): its bounding sphere and the
 * three.js objects that draw it, which it hides while another level shows.
 */
import { type BufferAttribute, type InstancedMesh, type Object3D, Sphere, Vector3 } from 'three';
import { LEAF_MATRICES_KEY } from 'sylva-trees/viewer';
import type { TreeBuffers } from 'sylva-trees/core';

/** The tree's bounding sphere from its bark bounds and its leaves (position ± length). */
export function sphereOf(buffers: TreeBuffers): Sphere {
  const { min, max } = buffers.meta.bounds;
  const lo = [...min];
  const hi = [...max];
  const m = buffers.foliage?.matrices ?? new Float32Array(0);
  for (let o = 0; o + 16 <= m.length; o += 16) {
    const len = Math.hypot(m[o + 4]!, m[o + 5]!, m[o + 6]!);
    for (let k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k]!, m[o + 12 + k]! - len);
      hi[k] = Math.max(hi[k]!, m[o + 12 + k]! + len);
    }
  }
  const centre = new Vector3((lo[0]! + hi[0]!) / 2, (lo[1]! + hi[1]!) / 2, (lo[2]! + hi[2]!) / 2);
  return new Sphere(
    centre,
    Math.max(Math.hypot(hi[0]! - lo[0]!, hi[1]! - lo[1]!, hi[2]! - lo[2]!) / 2, 0.01),
  );
}

/**
 * The viewer's LOD0 objects: the mesh wrapping the tree's position array and the instanced
 * leaves wrapping its leaf matrices (the viewer hands the transferred arrays to three.js without
 * copying); failing that, meshes of the same vertex / instance counts.
 */
export function findBaseObjects(
  scene: Object3D,
  buffers: TreeBuffers,
  ...skip: Object3D[]
): Object3D[] {
  const vertices = buffers.positions.length / 3;
  const leaves = buffers.foliage ? buffers.foliage.colors.length / 3 : 0;
  const bark: [Object3D[], Object3D[]] = [[], []];
  const leaf: [Object3D[], Object3D[]] = [[], []];
  const visit = (o: Object3D) => {
    if (skip.includes(o)) return;
    const mesh = o as Partial<InstancedMesh>;
    if (mesh.isMesh && mesh.geometry) {
      const position = mesh.geometry.getAttribute('position');
      const pulled: unknown = o.userData[LEAF_MATRICES_KEY];
      if (pulled !== undefined) {
        if (pulled === buffers.foliage?.matrices) leaf[0].push(o);
      } else if (mesh.isInstancedMesh) {
        if (mesh.instanceMatrix?.array === buffers.foliage?.matrices) leaf[0].push(o);
        else if (leaves > 0 && mesh.count === leaves) leaf[1].push(o);
      } else if (position) {
        if ((position as BufferAttribute).array === buffers.positions) bark[0].push(o);
        else if (position.count === vertices) bark[1].push(o);
      }
    }
    for (const child of o.children) visit(child);
  };
  visit(scene);
  return [...(bark[0].length > 0 ? bark[0] : bark[1]), ...(leaf[0].length > 0 ? leaf[0] : leaf[1])];
}
