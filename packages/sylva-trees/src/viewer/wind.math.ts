/**
 * Wind displacement in plain TypeScript: a line-by-line mirror of the GLSL in `wind.ts`, so the
 * formulas can be unit-tested (and reused by exporters or CPU-side picking).
 *
 * After GPU Gems 3, ch. 16 ("Vegetation Procedural Animation and Shading in Crysis"):
 *
 * - **Main bending** of the whole tree about its base: `f = y·bendScale + 1; f = f² − f`, offset
 *   `xz` by `wind·f`, then rescale to the original distance from the base (the tree bends, it
 *   does not stretch).
 * - **Branch sway**: smooth triangle waves whose phase travels across the crown with the wind;
 *   the amplitude grows with the horizontal distance from the trunk axis (and fades out toward
 *   the ground). It is a continuous
 *   function of position, so branch junctions never crack and leaves (which only know where they
 *   are attached) follow their twigs exactly.
 * - **Twig bending** (bark with per-vertex wind data only): each stem swings about its pivot
 *   with its own phase (`phase` + a hash of the pivot); the amplitude grows with `1 − stiffness`
 *   and with the branch level and is zero at the pivot.
 * - **Leaf flutter** (instanced leaves): the blade moves along its normal, more toward its tip
 *   and edges, with a per-leaf phase hashed from the attachment point.
 * - **Gusts**: a slow sum of sines scales the strength by `1 + gust · envelope(t)`.
 *
 * Coordinates: metres, Y up, the tree's base at the origin (as the core builds it).
 */

export type Vec3 = [number, number, number];

/** The uniform values of one frame. */
export interface WindFrame {
  /** Seconds (`uWindTime`). */
  time: number;
  /** Unit vector in the ground plane: `[x, z]` the wind blows toward (`uWindDirection`). */
  direction: [number, number];
  /** 0 (calm) .. 2 (storm) (`uWindStrength`). */
  strength: number;
  /** `[amplitude 0..1, frequency Hz]` (`uWindGust`). */
  gust: [number, number];
  /** `uWindEnabled`. */
  enabled: boolean;
  /** Tree height and crown radius in metres (`uWindTree.xy`). */
  height: number;
  radius: number;
}

/** The core's per-vertex wind data (`TreeMesh.wind`, 8 floats). */
export interface WindVertex {
  pivot: Vec3;
  level: number;
  phase: number;
  stiffness: number;
  distance: number;
  radius: number;
}

/** Main bending: top displacement per unit strength as a share of the tree height (f = 2 there). */
export const MAIN_BEND = 0.02;
/** Branch sway amplitude per unit strength as a share of the tree height (at the crown edge). */
export const BRANCH_SWAY = 0.012;
/** Twig bending: largest swing angle per unit strength (radians). */
export const TWIG_ANGLE = 0.05;
/** Leaf flutter amplitude per unit strength, in leaf lengths. */
export const LEAF_FLUTTER = 0.12;

const TAU = Math.PI * 2;

function fract(x: number): number {
  return x - Math.floor(x);
}

function clamp(x: number, lo: number, hi: number): number {
  return Math.min(Math.max(x, lo), hi);
}

/** `x²(3 − 2x)`: the Hermite smoothing of GPU Gems 3 (listing 16-3). */
export function smoothCurve(x: number): number {
  return x * x * (3 - 2 * x);
}

/** Triangle wave of period 1: 0 at integers, 1 at half-integers. */
export function triangleWave(x: number): number {
  return Math.abs(fract(x + 0.5) * 2 - 1);
}

/** `SmoothCurve(TriangleWave(x))`: a cheap sine look-alike, range 0..1, period 1. */
export function smoothTriangleWave(x: number): number {
  return smoothCurve(triangleWave(x));
}

/** Sum of two smooth triangle waves, centred: range −1..1. */
export function wave2(a: number, b: number): number {
  return smoothTriangleWave(a) + smoothTriangleWave(b) - 1;
}

/** Hash of a point to 0..1 (Dave Hoskins' `hash13`), as in the shader. */
export function hash3(p: Vec3): number {
  let x = fract(p[0] * 0.1031);
  let y = fract(p[1] * 0.1031);
  let z = fract(p[2] * 0.1031);
  const d = x * (z + 31.32) + y * (y + 31.32) + z * (x + 31.32);
  x += d;
  y += d;
  z += d;
  return fract((x + y) * z);
}

/** Gust envelope 0..1 at time `t` for a gust frequency (Hz): slow, smooth, never periodic-looking. */
export function gustEnvelope(t: number, frequency: number): number {
  const s =
    0.5 +
    0.5 * (0.6 * Math.sin(TAU * frequency * t) + 0.4 * Math.sin(TAU * frequency * 2.31 * t + 1.3));
  return s * s;
}

/** Strength at time `t` with gusts (0 when wind is off). */
export function effectiveStrength(frame: WindFrame): number {
  if (!frame.enabled) return 0;
  return frame.strength * (1 + frame.gust[0] * gustEnvelope(frame.time, frame.gust[1]));
}

/** Main bending of a point about the tree base (strength `s` from `effectiveStrength`). */
export function mainBend(p: Vec3, frame: WindFrame, s: number): Vec3 {
  const h = Math.max(frame.height, 0.1);
  const t = frame.time;
  const sway = 1 + 0.4 * wave2(t * 0.23, t * 0.137 + 0.3);
  const amount = s * sway * MAIN_BEND * h;
  const y = Math.max(p[1], 0);
  let f = y / h + 1;
  f = f * f - f;
  const q: Vec3 = [
    p[0] + frame.direction[0] * amount * f,
    p[1],
    p[2] + frame.direction[1] * amount * f,
  ];
  const len = Math.hypot(p[0], p[1], p[2]);
  const qLen = Math.hypot(q[0], q[1], q[2]);
  if (len < 1e-6 || qLen < 1e-6) return [p[0], p[1], p[2]];
  const k = len / qLen;
  return [q[0] * k, q[1] * k, q[2] * k];
}

/** Branch sway offset at a point: continuous in space (see the module comment). */
export function branchSway(p: Vec3, frame: WindFrame, s: number): Vec3 {
  const h = Math.max(frame.height, 0.1);
  const r = Math.max(frame.radius, 0.1);
  const t = frame.time;
  const [dx, dz] = frame.direction;
  let flex = clamp(Math.hypot(p[0], p[2]) / r, 0, 1);
  // Out from the trunk axis, and up from the ground (roots and the trunk base stay put).
  flex *= flex * clamp(p[1] / (0.25 * h), 0, 1);
  // The phase travels downwind (a gust front crossing the crown) and varies across it.
  const phase = -(p[0] * dx + p[2] * dz) * 0.12 + (p[0] * 0.19 + p[1] * 0.07 + p[2] * 0.23);
  const sway = wave2(t * 0.375 + phase, t * 0.193 + phase * 1.37);
  const bob = wave2(t * 0.61 + phase * 1.7 + 0.25, t * 0.29 + phase * 0.83 + 0.5);
  const amp = s * flex * BRANCH_SWAY * h;
  return [dx * sway * amp, 0.5 * bob * amp, dz * sway * amp];
}

/** Twig bending offset of a bark vertex about its stem's pivot (per-vertex data). */
export function twigBend(p: Vec3, v: WindVertex, frame: WindFrame, s: number): Vec3 {
  const t = frame.time;
  const r: Vec3 = [p[0] - v.pivot[0], p[1] - v.pivot[1], p[2] - v.pivot[2]];
  const along = Math.hypot(r[0], r[1], r[2]);
  if (along < 1e-6) return [0, 0, 0];
  const level = clamp(v.level / 3, 0, 1);
  const bend = 1 - clamp(v.stiffness, 0, 1);
  const gain = bend * bend * bend * bend * level * level;
  const phase = v.phase + hash3(v.pivot);
  const w = wave2(t * 0.793 + phase, t * 0.375 + phase * 1.3);
  const angle = s * TWIG_ANGLE * gain * w;
  // Swing toward a mix of the wind and up, perpendicular to the stem.
  const [dx, dz] = frame.direction;
  const wl = Math.hypot(dx, 0.35, dz);
  const wv: Vec3 = [dx / wl, 0.35 / wl, dz / wl];
  const rn: Vec3 = [r[0] / along, r[1] / along, r[2] / along];
  const d = rn[0] * wv[0] + rn[1] * wv[1] + rn[2] * wv[2];
  const k = angle * along;
  return [(wv[0] - rn[0] * d) * k, (wv[1] - rn[1] * d) * k, (wv[2] - rn[2] * d) * k];
}

/** A bark vertex after wind; `v` is its per-vertex data (null: none from the core). */
export function displaceBark(p: Vec3, frame: WindFrame, v: WindVertex | null): Vec3 {
  const s = effectiveStrength(frame);
  if (s <= 0) return [p[0], p[1], p[2]];
  const b = branchSway(p, frame, s);
  const q: Vec3 = [p[0] + b[0], p[1] + b[1], p[2] + b[2]];
  // (A vertex without data reads constant defaults on the GPU: distance 0, so no twig term.)
  if (v && v.distance > 0) {
    const tw = twigBend(p, v, frame, s);
    q[0] += tw[0];
    q[1] += tw[1];
    q[2] += tw[2];
  }
  return mainBend(q, frame, s);
}

/** Leaf flutter offset in leaf units (`local`: leaf mesh vertex; `normal`: its normal). */
export function leafFlutter(
  local: Vec3,
  normal: Vec3,
  anchor: Vec3,
  frame: WindFrame,
  s: number,
): Vec3 {
  const t = frame.time;
  const ph = hash3([anchor[0] * 7.31, anchor[1] * 7.31, anchor[2] * 7.31]);
  const vtx = local[0] * 0.37 + local[1] * 0.71;
  const w = wave2(t * 1.975 + ph + vtx, t * 0.793 + ph * 1.7 + vtx);
  const edge = Math.max(local[1], 0) + Math.abs(local[0]);
  const k = w * edge * LEAF_FLUTTER * Math.min(s, 1.5);
  return [normal[0] * k, normal[1] * k, normal[2] * k];
}

/**
 * Where a leaf's attachment point goes: the main bending and branch sway of the point, the
 * same as a bark vertex there without twig data (so leaves stay on their twigs).
 */
export function displaceAnchor(anchor: Vec3, frame: WindFrame): Vec3 {
  return displaceBark(anchor, frame, null);
}
