/**
 * Hand edits (paint growth, draw the crown, cut a branch, bend a branch): the ordered edit list,
 * its limits and a strict validator with the core's messages (`edits[3].radius is 0: allowed
 * range is 0.02 to 10 m`). It mirrors the core's model in
 * `core-rs/sylva-core/src/params/edits.rs` (limits) and `params/edits/validate.rs` (checks);
 * docs/formats.md documents the JSON. Coordinates are in tree space: metres, y up, the origin at
 * the trunk's base. The JSON document and the core's input are in `editsJson.ts`.
 */
import type { SylvaError } from './types';

/** A point in tree space (m). */
export type EditPoint = [number, number, number];

/** One paint stroke: markers in a tube of `radius` around `points`, grown toward. */
export interface PaintEdit {
  op: 'paint';
  /** The brush points in drawing order (m). */
  points: EditPoint[];
  /** Tube radius (m). */
  radius: number;
  /** Markers per cubic metre. */
  density: number;
  /** Internode length of the new growth (m). */
  segment: number;
  /** Kill distance of the markers (m), at least `segment`. */
  kill: number;
}

/** A drawn crown outline: `[radius from the trunk axis, height]` pairs (m), closed. */
export interface CrownEdit {
  op: 'crown';
  outline: [number, number][];
}

/**
 * Cut the stem nearest to `at` there. A dated cut (`year`, the tree's Age when it was made) has
 * not happened while the tree is younger; later, woundwood closes over its face a ring a year.
 */
export interface CutEdit {
  op: 'cut';
  at: EditPoint;
  /** The tree's Age when the cut was made (years, within `YEAR_RANGE`); absent: undated. */
  year?: number;
}

/** Bend the stem nearest to `at` so that its point at `at` follows to `to`. */
export interface BendEdit {
  op: 'bend';
  at: EditPoint;
  to: EditPoint;
}

/** One entry of the edit list. */
export type Edit = PaintEdit | CrownEdit | CutEdit | BendEdit;

/** The op names, in the order the messages list them. */
export const EDIT_OPS = ['paint', 'crown', 'cut', 'bend'] as const;

export type { EditReport } from './types';

// The core's limits (core-rs/sylva-core/src/params/edits.rs); keep in step with it.
/** Most edits one tree may carry. */
export const MAX_EDITS = 1000;
/** Most points in one paint stroke. */
export const MAX_STROKE_POINTS = 4096;
/** Most points in one crown outline. */
export const MAX_OUTLINE_POINTS = 1024;
/** Most points in all strokes and outlines together. */
export const MAX_EDIT_POINTS = 65536;
/** Largest |coordinate| along any axis (m). */
export const MAX_COORD = 200;
/** Allowed paint brush radius (m). */
export const RADIUS_RANGE: readonly [number, number] = [0.02, 10];
/** Allowed paint density (markers per m³). */
export const DENSITY_RANGE: readonly [number, number] = [1, 5000];
/** Allowed paint segment length (m). */
export const SEGMENT_RANGE: readonly [number, number] = [0.02, 2];
/** Allowed paint kill distance (m). */
export const KILL_RANGE: readonly [number, number] = [0.02, 10];
/** Allowed year of a dated cut (years). */
export const YEAR_RANGE: readonly [number, number] = [0, 300];
/** A cut or bend at or below this height names the ground (m). */
export const GROUND = 0.05;
/** Version of the edit list document. */
export const EDITS_VERSION = 1;

/** The brush a new paint stroke uses (the Paint tool's defaults). */
export const DEFAULT_BRUSH = { radius: 0.6, density: 400, segment: 0.25, kill: 0.4 } as const;

/** A validation failure: `param` is the field's path, e.g. `edits[3].radius`. */
export class EditsError extends Error {
  override name = 'EditsError';
  constructor(
    readonly param: string,
    message: string,
  ) {
    super(message);
  }

  /** As the core reports it. */
  toSylvaError(): SylvaError {
    return { kind: 'invalid_param', param: this.param, message: this.message };
  }
}

/**
 * A number as the core prints an `f32` (`{}` in Rust): the shortest decimal that reads back as
 * the same `f32`, never in exponent form; `NaN`, `inf`, `-inf`.
 */
export function formatF32(value: number): string {
  const v = Math.fround(value);
  if (Number.isNaN(v)) return 'NaN';
  if (!Number.isFinite(v)) return v > 0 ? 'inf' : '-inf';
  if (v === 0) return Object.is(v, -0) ? '-0' : '0';
  for (let digits = 1; digits <= 9; digits++) {
    const text = v.toPrecision(digits);
    if (Math.fround(Number(text)) === v) return plainDecimal(Number(text));
  }
  return plainDecimal(v);
}

/** `value` in positional notation (no exponent). */
function plainDecimal(value: number): string {
  const text = String(value);
  if (!/e/i.test(text)) return text;
  return value.toLocaleString('en-US', { useGrouping: false, maximumSignificantDigits: 21 });
}

/** Throws unless `n ≤ MAX_EDITS`. */
export function checkCount(n: number): void {
  if (n > MAX_EDITS) {
    throw new EditsError('edits', `edits has ${n} edits: at most ${MAX_EDITS} are allowed`);
  }
}

/** Throws unless `min ≤ n ≤ max` points. */
export function checkPoints(field: string, n: number, max: number, min: number): void {
  if (n > max) {
    throw new EditsError(field, `${field} has ${n} points: at most ${max} are allowed`);
  }
  if (n < min) {
    throw new EditsError(field, `${field} has ${n} points: at least ${min} are needed`);
  }
}

function checkRange(field: string, v: number, [lo, hi]: readonly [number, number], unit: string) {
  const f = Math.fround(v);
  if (!Number.isFinite(f) || f < Math.fround(lo) || f > Math.fround(hi)) {
    throw new EditsError(
      field,
      `${field} is ${formatF32(v)}: allowed range is ${formatF32(lo)} to ${formatF32(hi)}${unit}`,
    );
  }
}

function checkCoord(field: string, v: number, lo: number): void {
  const f = Math.fround(v);
  if (!Number.isFinite(f) || f < lo || f > MAX_COORD) {
    throw new EditsError(
      field,
      `${field} is ${formatF32(v)}: allowed range is ${formatF32(lo)} to ${MAX_COORD} m`,
    );
  }
}

function checkVec3(field: string, q: readonly number[]): void {
  q.forEach((c, k) => checkCoord(`${field}[${k}]`, c, -MAX_COORD));
}

function checkAboveGround(field: string, q: EditPoint): void {
  checkVec3(field, q);
  if (Math.fround(q[1]) <= Math.fround(GROUND)) {
    throw new EditsError(
      field,
      `${field} is on the ground (y = ${formatF32(q[1])} m): a cut or bend names a branch above ${GROUND} m`,
    );
  }
}

function checkPaint(i: number, p: PaintEdit): void {
  const f = (name: string) => `edits[${i}].${name}`;
  checkPoints(f('points'), p.points.length, MAX_STROKE_POINTS, 1);
  p.points.forEach((q, k) => checkVec3(`${f('points')}[${k}]`, q));
  checkRange(f('radius'), p.radius, RADIUS_RANGE, ' m');
  checkRange(f('density'), p.density, DENSITY_RANGE, ' markers per m³');
  checkRange(f('segment'), p.segment, SEGMENT_RANGE, ' m');
  checkRange(f('kill'), p.kill, KILL_RANGE, ' m');
  if (Math.fround(p.kill) < Math.fround(p.segment)) {
    throw new EditsError(
      f('kill'),
      `${f('kill')} is ${formatF32(p.kill)}: it must be at least the segment length ${formatF32(p.segment)} m (else new shoots step past their markers)`,
    );
  }
}

function checkCrown(i: number, c: CrownEdit): void {
  const field = `edits[${i}].outline`;
  checkPoints(field, c.outline.length, MAX_OUTLINE_POINTS, 3);
  c.outline.forEach((q, k) => {
    checkCoord(`${field}[${k}][0]`, q[0], 0);
    checkCoord(`${field}[${k}][1]`, q[1], -MAX_COORD);
  });
  const crossing = firstCrossing(c.outline);
  if (crossing) {
    throw new EditsError(
      field,
      `${field} crosses itself (its edges ${crossing[0]} and ${crossing[1]} intersect): draw a simple closed outline`,
    );
  }
}

/**
 * Checks an edit list against the core's limits; throws an [`EditsError`] naming the first bad
 * edit and field, in the core's order and words.
 */
export function validateEdits(edits: readonly Edit[]): void {
  checkCount(edits.length);
  let points = 0;
  edits.forEach((e, i) => {
    const f = (name: string) => `edits[${i}].${name}`;
    switch (e.op) {
      case 'paint':
        points += e.points.length;
        checkPaint(i, e);
        break;
      case 'crown':
        points += e.outline.length;
        checkCrown(i, e);
        break;
      case 'cut':
        checkAboveGround(f('at'), e.at);
        if (e.year !== undefined) checkRange(f('year'), e.year, YEAR_RANGE, ' years');
        break;
      case 'bend':
        checkAboveGround(f('at'), e.at);
        checkVec3(f('to'), e.to);
        break;
    }
    if (points > MAX_EDIT_POINTS) {
      throw new EditsError(
        'edits',
        `the edits hold more than ${MAX_EDIT_POINTS} points in all (at edits[${i}]): split the work into fewer, shorter strokes`,
      );
    }
  });
}

/** The validation failure of `edits`, or null when they are good. */
export function editsProblem(edits: readonly Edit[]): EditsError | null {
  try {
    validateEdits(edits);
    return null;
  } catch (error) {
    if (error instanceof EditsError) return error;
    throw error;
  }
}

type P2 = readonly [number, number];

/**
 * The first pair of non-adjacent edges of the closed polygon `p` that meet (edge `k` runs from
 * `p[k]` to `p[k + 1]`, the last back to `p[0]`), or adjacent edges folding back onto each
 * other; null for a simple polygon. The core's `first_crossing`.
 */
export function firstCrossing(p: readonly P2[]): [number, number] | null {
  const n = p.length;
  const at = (k: number): P2 => p[k % n] as P2;
  for (let a = 0; a < n; a++) {
    for (let b = a + 1; b < n; b++) {
      const adjacent = b === a + 1 || (a === 0 && b === n - 1);
      const [p0, p1, q0, q1] = [at(a), at(a + 1), at(b), at(b + 1)];
      if (adjacent) {
        const [shared, x, y] = b === a + 1 ? [p1, p0, q1] : [p0, p1, q0];
        const u = [x[0] - shared[0], x[1] - shared[1]] as const;
        const v = [y[0] - shared[0], y[1] - shared[1]] as const;
        if (u[0] * v[1] - u[1] * v[0] === 0 && u[0] * v[0] + u[1] * v[1] > 0) return [a, b];
        continue;
      }
      if (segmentsMeet(p0, p1, q0, q1)) return [a, b];
    }
  }
  return null;
}

function side(p: P2, q: P2, r: P2): number {
  return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
}

function onBox(p: P2, q: P2, r: P2): boolean {
  return (
    r[0] >= Math.min(p[0], q[0]) &&
    r[0] <= Math.max(p[0], q[0]) &&
    r[1] >= Math.min(p[1], q[1]) &&
    r[1] <= Math.max(p[1], q[1])
  );
}

function segmentsMeet(a0: P2, a1: P2, b0: P2, b1: P2): boolean {
  const [d1, d2] = [side(b0, b1, a0), side(b0, b1, a1)];
  const [d3, d4] = [side(a0, a1, b0), side(a0, a1, b1)];
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  return (
    (d1 === 0 && onBox(b0, b1, a0)) ||
    (d2 === 0 && onBox(b0, b1, a1)) ||
    (d3 === 0 && onBox(a0, a1, b0)) ||
    (d4 === 0 && onBox(a0, a1, b1))
  );
}

/** A one-line summary of an edit for the edit list panel. */
export function summarizeEdit(e: Edit): string {
  const p = (q: readonly number[]) => q.map((c) => c.toFixed(2)).join(', ');
  switch (e.op) {
    case 'paint':
      return `${e.points.length} points, r ${e.radius} m, segment ${e.segment} m`;
    case 'crown':
      return `outline of ${e.outline.length} points`;
    case 'cut':
      return `at (${p(e.at)})${e.year === undefined ? '' : `, year ${e.year}`}`;
    case 'bend':
      return `(${p(e.at)}) → (${p(e.to)})`;
  }
}
