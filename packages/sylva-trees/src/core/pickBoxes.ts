/**
 * Boxes for picking the bark with a ray: the bark's triangles in index order, in runs of
 * [`PICK_RUN`] (the core writes them stem by stem, so a run is a compact piece of bark), each
 * with its axis-aligned box. The core computes them (`sylva_core::mesh::pick`, the session's
 * `pick_boxes`) and the worker sends them with the bark; [`pickBoxes`] is the same in
 * TypeScript (the worker's fallback for a core without them, and the tests' reference). The
 * viewer tests a ray against the boxes and only the triangles of the boxes it passes through
 * (`viewer/barkPick.ts`), instead of every triangle as three.js's `Mesh.raycast` does: the
 * brush, cut and bend tools pick on every pointer move.
 *
 * Layout: 6 floats per run, `min x, min y, min z, max x, max y, max z` (tree space, m); run `k`
 * holds triangles `k * PICK_RUN` to `min((k + 1) * PICK_RUN, triangles) - 1`.
 */

/** Triangles per box. */
export const PICK_RUN = 64;

/** The boxes of the runs of `indices` over `positions` (see the module doc). */
export function pickBoxes(positions: Float32Array, indices: Uint32Array): Float32Array {
  const triangles = Math.floor(indices.length / 3);
  const runs = Math.ceil(triangles / PICK_RUN);
  const out = new Float32Array(runs * 6);
  for (let r = 0; r < runs; r++) {
    let x0 = Infinity;
    let y0 = Infinity;
    let z0 = Infinity;
    let x1 = -Infinity;
    let y1 = -Infinity;
    let z1 = -Infinity;
    const end = Math.min(triangles, (r + 1) * PICK_RUN) * 3;
    for (let k = r * PICK_RUN * 3; k < end; k++) {
      const v = (indices[k] ?? 0) * 3;
      const x = positions[v] ?? 0;
      const y = positions[v + 1] ?? 0;
      const z = positions[v + 2] ?? 0;
      if (x < x0) x0 = x;
      if (x > x1) x1 = x;
      if (y < y0) y0 = y;
      if (y > y1) y1 = y;
      if (z < z0) z0 = z;
      if (z > z1) z1 = z;
    }
    out[r * 6] = x0;
    out[r * 6 + 1] = y0;
    out[r * 6 + 2] = z0;
    out[r * 6 + 3] = x1;
    out[r * 6 + 4] = y1;
    out[r * 6 + 5] = z1;
  }
  return out;
}
