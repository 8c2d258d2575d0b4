/**
 * Picking an `InstancedMesh` with a ray without three.js's per-instance work: its `raycast`
 * first computes a bounding sphere over every instance (a loop over every leaf after each new
 * tree) and then, per instance, copies the matrix, multiplies it and tests a transformed sphere.
 * This tests the ray against each instance's bounding sphere straight from the matrix array (a
 * few multiplications per instance), and runs three.js's exact test only on the instances the
 * ray passes near. Same hits, same `instanceId`s.
 */
import {
  Matrix4,
  Mesh,
  Ray,
  type InstancedMesh,
  type Intersection,
  type Object3D,
  type Raycaster,
} from 'three';

const inverse = new Matrix4();
const local = new Ray();
const instance = new Matrix4();
const world = new Matrix4();
const probe = new Mesh();
const found: Intersection<Object3D>[] = [];

/** `raycast` for `mesh` (see the module doc): pushes its hits onto `out`. */
export function pickInstances(
  mesh: InstancedMesh,
  raycaster: Raycaster,
  out: Intersection<Object3D>[],
): void {
  const geometry = mesh.geometry;
  // The instanced shape's own sphere (one leaf: a few dozen vertices).
  if (!geometry.boundingSphere) geometry.computeBoundingSphere();
  const sphere = geometry.boundingSphere;
  if (!sphere || mesh.count === 0) return;
  inverse.copy(mesh.matrixWorld).invert();
  local.copy(raycaster.ray).applyMatrix4(inverse);
  const { x: ox, y: oy, z: oz } = local.origin;
  const { x: dx, y: dy, z: dz } = local.direction;
  const { x: cx, y: cy, z: cz } = sphere.center;
  const r2 = sphere.radius * sphere.radius;
  const m = mesh.instanceMatrix.array;
  probe.geometry = geometry;
  probe.material = mesh.material;
  for (let i = 0; i < mesh.count; i++) {
    const k = i * 16;
    const m0 = m[k] ?? 0;
    const m1 = m[k + 1] ?? 0;
    const m2 = m[k + 2] ?? 0;
    const m4 = m[k + 4] ?? 0;
    const m5 = m[k + 5] ?? 0;
    const m6 = m[k + 6] ?? 0;
    const m8 = m[k + 8] ?? 0;
    const m9 = m[k + 9] ?? 0;
    const m10 = m[k + 10] ?? 0;
    // The sphere's centre in the mesh's space, relative to the ray's origin.
    const px = m0 * cx + m4 * cy + m8 * cz + (m[k + 12] ?? 0) - ox;
    const py = m1 * cx + m5 * cy + m9 * cz + (m[k + 13] ?? 0) - oy;
    const pz = m2 * cx + m6 * cy + m10 * cz + (m[k + 14] ?? 0) - oz;
    const scale2 = Math.max(
      m0 * m0 + m1 * m1 + m2 * m2,
      m4 * m4 + m5 * m5 + m6 * m6,
      m8 * m8 + m9 * m9 + m10 * m10,
    );
    const along = px * dx + py * dy + pz * dz;
    const behind = along < 0;
    const d2 = px * px + py * py + pz * pz - (behind ? 0 : along * along);
    if (d2 > r2 * scale2) continue;
    instance.fromArray(m, k);
    world.multiplyMatrices(mesh.matrixWorld, instance);
    probe.matrixWorld = world;
    probe.raycast(raycaster, found);
    for (const hit of found) {
      hit.instanceId = i;
      hit.object = mesh;
      out.push(hit);
    }
    found.length = 0;
  }
}
