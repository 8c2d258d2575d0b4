/**
 * Edits as the app keeps them: lengths rounded to centimetres and densities to whole markers per
 * m³, which is what the share link's `e=` carries (`url/editsCodec.ts`), so a link reproduces
 * the tree exactly. Values are also brought into the core's ranges where rounding or a tool could
 * leave them just outside (a cut at 5.4 cm would round onto the ground).
 */
import {
  DENSITY_RANGE,
  GROUND,
  KILL_RANGE,
  MAX_COORD,
  RADIUS_RANGE,
  SEGMENT_RANGE,
  YEAR_RANGE,
  type Edit,
  type EditPoint,
} from './edits';

/** Rounds to centimetres (no `-0`). */
export function roundCm(value: number): number {
  const r = Math.round(value * 100) / 100;
  return Object.is(r, -0) ? 0 : r;
}

function clamp(value: number, [lo, hi]: readonly [number, number]): number {
  return Math.min(hi, Math.max(lo, value));
}

const coord = (v: number) => roundCm(clamp(v, [-MAX_COORD, MAX_COORD]));
const point = (q: readonly number[]): EditPoint => [
  coord(q[0] ?? 0),
  coord(q[1] ?? 0),
  coord(q[2] ?? 0),
];
/** A branch point: above the ground's height after rounding. */
const above = (q: readonly number[]): EditPoint => {
  const p = point(q);
  return [p[0], Math.max(p[1], roundCm(GROUND + 0.01)), p[2]];
};

/** `e` on the share link's grid (see the module comment); the op and counts are unchanged. */
export function quantizeEdit(e: Edit): Edit {
  switch (e.op) {
    case 'paint': {
      const segment = roundCm(clamp(e.segment, SEGMENT_RANGE));
      return {
        op: 'paint',
        points: e.points.map(point),
        radius: roundCm(clamp(e.radius, RADIUS_RANGE)),
        density: Math.round(clamp(e.density, DENSITY_RANGE)),
        segment,
        kill: Math.max(segment, roundCm(clamp(e.kill, KILL_RANGE))),
      };
    }
    case 'crown':
      return {
        op: 'crown',
        outline: e.outline.map(([r, h]) => [roundCm(clamp(r, [0, MAX_COORD])), coord(h)]),
      };
    case 'cut':
      return e.year === undefined
        ? { op: 'cut', at: above(e.at) }
        : { op: 'cut', at: above(e.at), year: Math.round(clamp(e.year, YEAR_RANGE)) };
    case 'bend':
      return { op: 'bend', at: above(e.at), to: point(e.to) };
  }
}
