/** User volume primitives (growth mode): defaults, the core's JSON form and small helpers. */
import type { VolumeGroup, VolumeKind, VolumePrimitive } from './types';

/** Most primitives a tree may carry (the core's limit). */
export const MAX_VOLUMES = 32;
/** Smallest and largest radius, height or box extent (m; the core's limits). */
export const SIZE_MIN = 0.05;
export const SIZE_MAX = 100;
/** Largest |x|, |y|, |z| of a centre (m). */
export const CENTRE_MAX = 100;

/** The core's JSON form of one primitive (`radius`, `size` or `radius` + `height`). */
export function volumeToCore(v: VolumePrimitive): Record<string, unknown> {
  const base = { kind: v.kind, group: v.group, centre: v.centre };
  if (v.kind === 'sphere') return { ...base, radius: v.size[0] };
  if (v.kind === 'box') return { ...base, size: v.size };
  return { ...base, radius: v.size[0], height: v.size[1] };
}

/** Rounds to millimetres (what the share URL keeps), so a round trip is exact. */
export function roundMm(value: number): number {
  const r = Math.round(value * 1000) / 1000;
  return Object.is(r, -0) ? 0 : r;
}

function clampSize(value: number): number {
  return roundMm(Math.min(SIZE_MAX, Math.max(SIZE_MIN, value)));
}

function clampCentre(value: number): number {
  return roundMm(Math.min(CENTRE_MAX, Math.max(-CENTRE_MAX, value)));
}

/** A primitive with every number clamped to the core's ranges and rounded to millimetres. */
export function normalizeVolume(v: VolumePrimitive): VolumePrimitive {
  const [a, b, c] = v.size;
  const size: [number, number, number] =
    v.kind === 'sphere'
      ? [clampSize(a), clampSize(a), clampSize(a)]
      : v.kind === 'cylinder'
        ? [clampSize(a), clampSize(b), clampSize(a)]
        : [clampSize(a), clampSize(b), clampSize(c)];
  return {
    kind: v.kind,
    group: v.group,
    centre: [clampCentre(v.centre[0]), clampCentre(v.centre[1]), clampCentre(v.centre[2])],
    size,
  };
}

/** A new primitive of `kind` in `group`, placed in the middle of the default crown. */
export function newVolume(kind: VolumeKind, group: VolumeGroup, index: number): VolumePrimitive {
  const x = roundMm(((index % 5) - 2) * 1.5);
  const size: [number, number, number] =
    kind === 'sphere' ? [2, 2, 2] : kind === 'box' ? [3, 2, 3] : [1.5, 3, 1.5];
  return { kind, group, centre: [x, 5.5, 0], size };
}
