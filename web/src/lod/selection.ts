/**
 * Level-of-detail selection by screen size, with hysteresis. The measure is the tree's bounding
 * radius over the half height of the view at its distance, `s = R / (d · tan(fov / 2))`: 1 when
 * the bounding sphere just fills the view height, independent of the canvas size. A level is
 * kept while `s` stays above its threshold; the thresholds are chosen so that the next level's
 * geometric error (fewer sides, larger leaves, cloud, impostor pixels) stays under a pixel or
 * two of the canvases Sylva is viewed in, which is what keeps the silhouette.
 */

/** Levels: 0, 1, 2 (meshes) and 3 (the impostor). */
export const IMPOSTOR_LEVEL = 3;
/** Names shown in the UI. */
export const LEVEL_NAMES = ['LOD0', 'LOD1', 'LOD2', 'Impostor'] as const;

/**
 * Default thresholds of `s` below which a level gives way to the next one: LOD0 above 0.6, LOD1
 * down to 0.4, LOD2 down to 0.28, the impostor below (the viewer's fog hides the tree by
 * s ≈ 0.2, so the impostor must take over before that to be seen at all).
 */
export const VIEWER_THRESHOLDS: readonly number[] = [0.6, 0.4, 0.28];
/** Relative band around each threshold: switch coarser below t·(1−h), finer above t·(1+h). */
export const HYSTERESIS = 0.1;

/** Screen-size measure of a sphere of `radius` seen from `distance` with vertical `fovDeg`. */
export function screenFraction(radius: number, distance: number, fovDeg: number): number {
  const t = Math.tan((fovDeg * Math.PI) / 360);
  return radius / Math.max(distance * t, 1e-9);
}

/**
 * The level for screen size `s`, starting from `current`: coarser only once `s` drops below a
 * threshold by the hysteresis band, finer only once it rises above it by the band. Without a
 * current level (or with `h = 0`) this is the plain threshold choice.
 */
export function selectLod(
  current: number,
  s: number,
  thresholds: readonly number[] = VIEWER_THRESHOLDS,
  h: number = HYSTERESIS,
): number {
  let level = Math.min(Math.max(Math.round(current), 0), thresholds.length);
  while (level < thresholds.length && s < thresholds[level]! * (1 - h)) level++;
  while (level > 0 && s > thresholds[level - 1]! * (1 + h)) level--;
  return level;
}

/**
 * Distances (for a tree of radius 1 and scale 1) at which each threshold is crossed going
 * coarser (`out`) and finer (`back`): `d = R / (t (1 ∓ h) tan(fov/2))`. The forest compares
 * squared distances against these times the tree's radius.
 */
export function switchDistances(
  thresholds: readonly number[],
  fovDeg: number,
  h: number = HYSTERESIS,
): { out: number[]; back: number[] } {
  const t = Math.tan((fovDeg * Math.PI) / 360);
  return {
    out: thresholds.map((x) => 1 / (x * (1 - h) * t)),
    back: thresholds.map((x) => 1 / (x * (1 + h) * t)),
  };
}
