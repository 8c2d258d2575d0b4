/**
 * Hemi-octahedral mapping (the hemi-oct encoding of Cigolle et al., "A Survey of Efficient
 * Representations for Independent Unit Vectors", JCGT 3(2), 2014, as octahedral impostors use
 * it): unit directions of the upper hemisphere (y ≥ 0, Y up) ↔ points of the unit square. The
 * direction is projected onto the octahedron |x| + |y| + |z| = 1, its (x, z) rotated by 45° into
 * the square:
 *
 *   encode(d) = ((px + pz, px − pz) + 1) / 2  with  (px, pz) = (dx, dz) / (|dx| + |dy| + |dz|)
 *
 * so the zenith is the centre and the horizon the square's border, with +X, +Z, −X, −Z at the
 * corners (1, 1), (1, 0), (0, 0), (0, 1). An impostor atlas has `n × n` frames; frame
 * (i, j) is the view from `decode(i / (n − 1), j / (n − 1))`, so frames sit on the grid
 * vertices and any direction lies in one grid cell between 3 frames (two triangles per cell).
 * The same formulas are written in GLSL in `impostor.ts`; the tests check both agree.
 */

/** A 3D vector as a tuple. */
export type Vec3 = [number, number, number];

/** Unit direction (y < 0 is folded onto the horizon) → point of the unit square. */
export function hemiOctEncode(d: Vec3): [number, number] {
  const y = Math.max(d[1], 0);
  const sum = Math.abs(d[0]) + y + Math.abs(d[2]);
  if (sum === 0) return [0.5, 0.5];
  const px = d[0] / sum;
  const pz = d[2] / sum;
  return [(px + pz + 1) / 2, (px - pz + 1) / 2];
}

/** Point of the unit square → unit direction of the upper hemisphere. */
export function hemiOctDecode(u: number, v: number): Vec3 {
  const a = u * 2 - 1;
  const b = v * 2 - 1;
  const px = (a + b) / 2;
  const pz = (a - b) / 2;
  const y = Math.max(1 - Math.abs(px) - Math.abs(pz), 0);
  const len = Math.hypot(px, y, pz);
  return [px / len, y / len, pz / len];
}

/** The view direction of frame (i, j) of an `n × n` atlas. */
export function frameDirection(i: number, j: number, n: number): Vec3 {
  return hemiOctDecode(i / (n - 1), j / (n - 1));
}

/** Three frames and their barycentric weights (sum 1). */
export interface FrameBlend {
  frames: [[number, number], [number, number], [number, number]];
  weights: [number, number, number];
}

/**
 * The 3 frames around direction `d` in an `n × n` atlas and their weights: the grid cell that
 * holds `encode(d)`, split along its anti-diagonal into two triangles.
 */
export function frameBlend(d: Vec3, n: number): FrameBlend {
  const [u, v] = hemiOctEncode(d);
  const gx = u * (n - 1);
  const gy = v * (n - 1);
  const cx = Math.min(Math.floor(gx), n - 2);
  const cy = Math.min(Math.floor(gy), n - 2);
  const fx = gx - cx;
  const fy = gy - cy;
  if (fx + fy <= 1) {
    return {
      frames: [
        [cx, cy],
        [cx + 1, cy],
        [cx, cy + 1],
      ],
      weights: [1 - fx - fy, fx, fy],
    };
  }
  return {
    frames: [
      [cx + 1, cy + 1],
      [cx, cy + 1],
      [cx + 1, cy],
    ],
    weights: [fx + fy - 1, 1 - fx, 1 - fy],
  };
}

/** The nearest frame to direction `d` (the largest blend weight). */
export function nearestFrame(d: Vec3, n: number): [number, number] {
  const { frames, weights } = frameBlend(d, n);
  let best = 0;
  for (let k = 1; k < 3; k++) if (weights[k]! > weights[best]!) best = k;
  return frames[best]!;
}

/**
 * The image basis of the view from direction `d` (unit, pointing from the tree to the eye):
 * `right = normalize(Y × d)`, `up = d × right`; straight above, right = +X. This is the basis of
 * the camera `lookAt` builds with `up` as its up vector.
 */
export function viewBasis(d: Vec3): { right: Vec3; up: Vec3 } {
  // Y × d = (dz, 0, -dx)
  let rx = d[2];
  let rz = -d[0];
  const len = Math.hypot(rx, rz);
  if (len < 1e-6) {
    rx = 1;
    rz = 0;
  } else {
    rx /= len;
    rz /= len;
  }
  const right: Vec3 = [rx, 0, rz];
  // d × right
  const up: Vec3 = [d[1] * rz - d[2] * 0, d[2] * rx - d[0] * rz, d[0] * 0 - d[1] * rx];
  return { right, up };
}

/**
 * The eye ray `eye + t·w` (tree frame, centred on the bounding sphere's centre, in units of its
 * radius) in the orthographic view from unit direction `d`: `uv0` is where it crosses the view's
 * image plane through the centre, and at depth `h` (signed distance from that plane toward the
 * eye) it is at `uv0 + s·h`. Frame uv is `(p · right, p · up) / 2 + ½`.
 */
export function frameRay(
  d: Vec3,
  eye: Vec3,
  w: Vec3,
): { uv0: [number, number]; s: [number, number] } {
  const { right, up } = viewBasis(d);
  const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const den = Math.min(dot(w, d), -1e-4);
  const k = dot(eye, d) / den;
  const p0: Vec3 = [eye[0] - w[0] * k, eye[1] - w[1] * k, eye[2] - w[2] * k];
  return {
    uv0: [dot(p0, right) / 2 + 0.5, dot(p0, up) / 2 + 0.5],
    s: [dot(w, right) / (2 * den), dot(w, up) / (2 * den)],
  };
}

/** Most march steps per view (`impostor.frag.glsl` MAX_STEPS). */
export const MAX_PARALLAX_STEPS = 32;
/** How far behind a view's surface a ray may enter it and still hit it (radii). */
export const PARALLAX_THICKNESS = 0.03;

/** March steps for a ray moving `|s|` per unit depth in a frame of `cellPx` texels: ≤ 2 texels each. */
export function parallaxSteps(s: [number, number], cellPx: number): number {
  return Math.min(Math.max(Math.ceil(Math.hypot(s[0], s[1]) * cellPx), 2), MAX_PARALLAX_STEPS);
}

/**
 * Where the ray `uv0 + s·h` meets a view's surface, given `depth(uv)`: the surface's depth there
 * (radii toward the eye) or -2 where the view is empty. Marches h from 1 (the front of the
 * bounding sphere) to -1, bisects the first step that is behind the surface 4 times, and accepts
 * the crossing if the ray enters no more than {@link PARALLAX_THICKNESS} behind the surface
 * (else it passes behind, e.g. beside a trunk, and marches on). Null: the ray misses this view.
 */
export function parallaxHit(
  depth: (uv: [number, number]) => number,
  uv0: [number, number],
  s: [number, number],
  cellPx: number,
): [number, number] | null {
  const at = (h: number): [number, number] => [uv0[0] + s[0] * h, uv0[1] + s[1] * h];
  const n = parallaxSteps(s, cellPx);
  const dh = 2 / n;
  let hPrev = 1;
  let fPrev = depth(at(1)) - 1;
  for (let k = 1; k <= n; k++) {
    const h = 1 - dh * k;
    const f = depth(at(h)) - h;
    if (f >= 0 && fPrev < 0) {
      let front = hPrev;
      let back = h;
      let fb = f;
      for (let b = 0; b < 4; b++) {
        const mid = (front + back) / 2;
        const fm = depth(at(mid)) - mid;
        if (fm >= 0) {
          back = mid;
          fb = fm;
        } else front = mid;
      }
      if (fb <= PARALLAX_THICKNESS) return at(back);
    } else if (f >= 0 && f <= PARALLAX_THICKNESS) {
      return at(h);
    }
    hPrev = h;
    fPrev = f;
  }
  return null;
}
