/**
 * Screen to tree space for the hand-edit tools (no DOM): where a brush point lands when the
 * cursor is over no branch (the plane through the trunk axis facing the camera), where a bend's
 * target lies (the plane through the grabbed point facing the camera), and how an outline drawn
 * from the side becomes the crown's `[radius, height]` profile. Tree space is the scene's world
 * space: metres, y up, the trunk's base at the origin (docs/formats.md).
 */
import { Plane, Vector3, type Camera, type Ray } from 'three';

/** Heights at which a drawn outline's half-width is measured. */
export const OUTLINE_SAMPLES = 16;
/** Smallest radius of the profile between its ends (m): the outline never touches the axis. */
export const MIN_PROFILE_RADIUS = 0.05;
/** A crown outline is drawn from the side: the view may tilt at most this far (|forward.y|). */
export const MAX_SIDE_TILT = 0.6;

const UP = new Vector3(0, 1, 0);

/** The camera's view direction. */
function forward(camera: Camera): Vector3 {
  return camera.getWorldDirection(new Vector3());
}

/**
 * The vertical plane through the trunk axis (the y axis) facing the camera: its normal is the
 * view direction made horizontal (looking straight down: the view's up vector instead).
 */
export function trunkPlane(camera: Camera): Plane {
  const f = forward(camera);
  const normal = new Vector3(f.x, 0, f.z);
  if (normal.lengthSq() < 1e-8) normal.copy(camera.up).applyQuaternion(camera.quaternion).setY(0);
  if (normal.lengthSq() < 1e-8) normal.set(0, 0, 1);
  return new Plane().setFromNormalAndCoplanarPoint(normal.normalize(), new Vector3());
}

/** The plane through `point` facing the camera (normal: the view direction). */
export function facingPlane(camera: Camera, point: Vector3): Plane {
  return new Plane().setFromNormalAndCoplanarPoint(forward(camera), point);
}

/** Where `ray` meets `plane`, or null when it runs parallel or away from it. */
export function onPlane(ray: Ray, plane: Plane): Vector3 | null {
  return ray.intersectPlane(plane, new Vector3());
}

/**
 * A brush point: the surface hit under the cursor if there is one, else the point on the trunk
 * plane (null when the ray misses that plane too, e.g. pointing at the sky parallel to it).
 */
export function brushPoint(hit: Vector3 | null, ray: Ray, camera: Camera): Vector3 | null {
  return hit ? hit.clone() : onPlane(ray, trunkPlane(camera));
}

/** Whether the camera looks from the side enough to draw a crown outline. */
export function looksFromSide(camera: Camera): boolean {
  return Math.abs(forward(camera).y) <= MAX_SIDE_TILT;
}

/**
 * The `[radius, height]` profile of an outline drawn in the trunk plane (`points`, world space),
 * revolved about the trunk axis: at each of `OUTLINE_SAMPLES` heights between the outline's
 * lowest and highest point, the farthest the outline reaches from the axis on either side. The
 * profile runs up the outside from the axis at the bottom to the axis at the top (the closing
 * edge runs down the axis), so it is a simple closed outline whatever was drawn. Null for an
 * outline less than 10 cm tall or wide.
 */
export function crownProfile(
  points: readonly Vector3[],
  camera: Camera,
): [number, number][] | null {
  if (points.length < 3) return null;
  const plane = trunkPlane(camera);
  // The horizontal axis in the plane: signed distance from the trunk axis.
  const side = new Vector3().crossVectors(UP, plane.normal).normalize();
  const flat = points.map((p) => [p.dot(side), p.y] as const);
  const heights = flat.map(([, y]) => y);
  const bottom = Math.max(0, Math.min(...heights));
  const top = Math.max(...heights);
  const reach = Math.max(...flat.map(([s]) => Math.abs(s)));
  if (top - bottom < 0.1 || reach < 0.1) return null;
  const profile: [number, number][] = [[0, bottom]];
  for (let i = 1; i <= OUTLINE_SAMPLES; i++) {
    const h = bottom + ((top - bottom) * i) / (OUTLINE_SAMPLES + 1);
    profile.push([Math.max(MIN_PROFILE_RADIUS, halfWidth(flat, h)), h]);
  }
  profile.push([0, top]);
  return profile;
}

/** The largest |s| where the closed polyline `flat` (s, y) crosses height `h` (0 if nowhere). */
export function halfWidth(flat: readonly (readonly [number, number])[], h: number): number {
  let widest = 0;
  for (let i = 0; i < flat.length; i++) {
    const a = flat[i];
    const b = flat[(i + 1) % flat.length];
    if (!a || !b) continue;
    const [lo, hi] = a[1] <= b[1] ? [a, b] : [b, a];
    if (h < lo[1] || h > hi[1] || hi[1] === lo[1]) continue;
    const t = (h - lo[1]) / (hi[1] - lo[1]);
    widest = Math.max(widest, Math.abs(lo[0] + (hi[0] - lo[0]) * t));
  }
  return widest;
}

/** Pointer position in normalised device coordinates of `element` (x right, y up, −1..1). */
export function toNdc(
  clientX: number,
  clientY: number,
  rect: { left: number; top: number; width: number; height: number },
): [number, number] {
  return [
    ((clientX - rect.left) / Math.max(1, rect.width)) * 2 - 1,
    -((clientY - rect.top) / Math.max(1, rect.height)) * 2 + 1,
  ];
}
