/**
 * Picking the bark with a ray through its pick boxes (`core/pickBoxes.ts`): the ray, brought
 * into the mesh's space, is tested against each run's box and, only where it passes through one,
 * against that run's triangles. It reports the **nearest** hit only (what the tools ask for: the
 * surface under the cursor), with the triangle's index; with no boxes for the current arrays it
 * falls back to three.js's `Mesh.raycast` (every triangle).
 */
import {
  BackSide,
  DoubleSide,
  Matrix4,
  Mesh,
  Ray,
  Vector3,
  type BufferGeometry,
  type Intersection,
  type Material,
  type Object3D,
  type Raycaster,
} from 'three';
import { PICK_RUN } from '../core/pickBoxes';

const inverse = new Matrix4();
const local = new Ray();
const a = new Vector3();
const b = new Vector3();
const c = new Vector3();
const hit = new Vector3();

/** The slab interval `[t0, t1]` of one axis narrowed by box bounds `lo..hi` (NaN-safe). */
function slab(
  t: [number, number],
  lo: number,
  hi: number,
  origin: number,
  invDir: number,
): boolean {
  const p = (lo - origin) * invDir;
  const q = (hi - origin) * invDir;
  // A ray along a box face (0 × ∞): no bound from this axis.
  if (Number.isNaN(p) || Number.isNaN(q)) return t[0] <= t[1];
  t[0] = Math.max(t[0], Math.min(p, q));
  t[1] = Math.min(t[1], Math.max(p, q));
  return t[0] <= t[1];
}

const span: [number, number] = [0, Infinity];

/** Whether the ray `o + t d` (t ≥ 0, `inv` = 1 / d) passes through box `k` of `boxes`. */
function throughBox(boxes: Float32Array, k: number, o: Vector3, inv: Vector3): boolean {
  const j = k * 6;
  span[0] = 0;
  span[1] = Infinity;
  return (
    slab(span, boxes[j] ?? 0, boxes[j + 3] ?? 0, o.x, inv.x) &&
    slab(span, boxes[j + 1] ?? 0, boxes[j + 4] ?? 0, o.y, inv.y) &&
    slab(span, boxes[j + 2] ?? 0, boxes[j + 5] ?? 0, o.z, inv.z)
  );
}

/** Which sides of a triangle of material `m` a ray hits: `front` culls back faces. */
function culls(materials: Material | Material[]): boolean {
  const list = Array.isArray(materials) ? materials : [materials];
  return list.every((m) => m.side !== DoubleSide && m.side !== BackSide);
}

/**
 * The nearest hit of `raycaster`'s ray on `mesh` (pushed onto `out`), through `boxes` when they
 * were computed for the geometry's current index (see the module doc).
 */
export function pickBark(
  mesh: Mesh<BufferGeometry, Material | Material[]>,
  boxes: Float32Array | null,
  raycaster: Raycaster,
  out: Intersection<Object3D>[],
): void {
  const geometry = mesh.geometry;
  const index = geometry.index?.array;
  const position = geometry.getAttribute('position')?.array;
  const triangles = index ? Math.floor(index.length / 3) : 0;
  if (
    !boxes ||
    !index ||
    !(position instanceof Float32Array) ||
    boxes.length !== Math.ceil(triangles / PICK_RUN) * 6
  ) {
    Mesh.prototype.raycast.call(mesh, raycaster, out);
    return;
  }
  inverse.copy(mesh.matrixWorld).invert();
  local.copy(raycaster.ray).applyMatrix4(inverse);
  const o = local.origin;
  const inv = new Vector3(1 / local.direction.x, 1 / local.direction.y, 1 / local.direction.z);
  const backfaceCulling = culls(mesh.material);
  let best = Infinity;
  let bestFace = -1;
  const point = new Vector3();
  const runs = boxes.length / 6;
  for (let r = 0; r < runs; r++) {
    if (!throughBox(boxes, r, o, inv)) continue;
    const end = Math.min(triangles, (r + 1) * PICK_RUN);
    for (let f = r * PICK_RUN; f < end; f++) {
      a.fromArray(position, (index[f * 3] ?? 0) * 3);
      b.fromArray(position, (index[f * 3 + 1] ?? 0) * 3);
      c.fromArray(position, (index[f * 3 + 2] ?? 0) * 3);
      if (!local.intersectTriangle(a, b, c, backfaceCulling, hit)) continue;
      const t = hit.distanceToSquared(o);
      if (t < best) {
        best = t;
        bestFace = f;
        point.copy(hit);
      }
    }
  }
  if (bestFace < 0) return;
  point.applyMatrix4(mesh.matrixWorld);
  const distance = raycaster.ray.origin.distanceTo(point);
  if (distance < raycaster.near || distance > raycaster.far) return;
  out.push({ distance, point, object: mesh, faceIndex: bestFace });
}
