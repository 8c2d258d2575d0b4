/**
 * `InstancedMesh` over instance data that already exists (the worker's transferred matrices and
 * colours, or a forest's shared buffer). three.js's constructor allocates a matrix array of its
 * own and writes an identity matrix into it per instance, a JavaScript loop over every leaf on
 * the main thread that the next line throws away; this builds the mesh with none and hands it
 * the given arrays, and a `raycast` that skips the per-instance work (`instancePick.ts`).
 */
import { InstancedBufferAttribute, InstancedMesh, type BufferGeometry, type Material } from 'three';
import { pickInstances } from './instancePick';

/** An instanced mesh drawing `count` instances (all of `matrices` by default). */
export function wrapInstances(
  geometry: BufferGeometry,
  material: Material | Material[],
  matrices: InstancedBufferAttribute | Float32Array,
  colors?: InstancedBufferAttribute | Float32Array | null,
  count?: number,
): InstancedMesh {
  const mesh = new InstancedMesh(geometry, material, 0);
  mesh.instanceMatrix =
    matrices instanceof Float32Array ? new InstancedBufferAttribute(matrices, 16) : matrices;
  if (colors) {
    mesh.instanceColor =
      colors instanceof Float32Array ? new InstancedBufferAttribute(colors, 3) : colors;
  }
  mesh.count = count ?? mesh.instanceMatrix.count;
  // A ray picks through each instance's sphere, without three.js's loop over every instance.
  mesh.raycast = (raycaster, hits) => pickInstances(mesh, raycaster, hits);
  return mesh;
}
