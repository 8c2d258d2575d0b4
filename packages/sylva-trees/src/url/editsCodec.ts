/**
 * The hand edit list in a share link: `e=1~p60.400.25.40.120.600.30.5.2.-1~c80.410.-20`. A
 * version, then one item per edit joined by `~`: an op letter and whole numbers joined by `.`,
 * lengths in centimetres (so no character needs %-encoding):
 *
 * - `p` paint: radius, density (markers per m³), segment, kill, then the points' x,y,z: the
 *   first point as it is, every next one as the difference to the one before;
 * - `o` crown outline: the points' radius,height, the first as it is, the next as differences;
 * - `c` cut: at x,y,z, then for a dated cut its year (whole years);
 * - `b` bend: at x,y,z, to x,y,z.
 *
 * Decoding is strict and all-or-nothing (an edit list is ordered; a list with a hole would be
 * another tree): a value past [`MAX_EDITS_LINK_LENGTH`], an unknown version or op, a number that
 * is not a plain integer, a wrong count or an edit the validator rejects drops every edit, with
 * one message naming what was wrong. docs/formats.md documents the form.
 */
import { validateEdits, EditsError, MAX_EDITS, type Edit, type EditPoint } from '../core/edits';
import { quantizeEdit } from '../core/editsQuantize';

/** Query key of the edit list. */
export const EDITS_KEY = 'e';
/** Version prefix of the `e=` value. */
export const EDITS_LINK_VERSION = '1';
/** Longest `e=` value written or read (characters); a longer history stays out of the link. */
export const MAX_EDITS_LINK_LENGTH = 2000;

/** A whole number as the link writes it: an optional minus and at most 7 digits. */
const INT_RE = /^-?\d{1,7}$/;

const cm = (metres: number): number => {
  const r = Math.round(metres * 100);
  return Object.is(r, -0) ? 0 : r;
};
const metres = (centimetres: number): number => {
  const m = centimetres / 100;
  return Object.is(m, -0) ? 0 : m;
};

/** Absolute first tuple, then differences (integers in, integers out). */
function deltas(tuples: readonly (readonly number[])[]): number[] {
  const out: number[] = [];
  tuples.forEach((t, i) => {
    const prev = tuples[i - 1];
    t.forEach((v, k) => out.push(prev ? cm(v) - cm(prev[k] ?? 0) : cm(v)));
  });
  return out;
}

/** The inverse of `deltas`: tuples of `width` in metres. */
function undeltas(values: readonly number[], width: number): number[][] {
  const out: number[][] = [];
  const running = new Array<number>(width).fill(0);
  for (let i = 0; i < values.length; i += width) {
    for (let k = 0; k < width; k++) running[k] = (running[k] ?? 0) + (values[i + k] ?? 0);
    out.push(running.map(metres));
  }
  return out;
}

function encodeEdit(e: Edit): string {
  switch (e.op) {
    case 'paint':
      return `p${[cm(e.radius), Math.round(e.density), cm(e.segment), cm(e.kill), ...deltas(e.points)].join('.')}`;
    case 'crown':
      return `o${deltas(e.outline).join('.')}`;
    case 'cut':
      return `c${[...e.at.map(cm), ...(e.year === undefined ? [] : [Math.round(e.year)])].join('.')}`;
    case 'bend':
      return `b${[...e.at, ...e.to].map(cm).join('.')}`;
  }
}

/**
 * The `e=` value of `edits` (quantised to centimetres and whole markers per m³; the app keeps
 * its edits quantised, so the link gives the same tree). Empty list: empty string (no key).
 */
export function encodeEdits(edits: readonly Edit[]): string {
  if (edits.length === 0) return '';
  return [EDITS_LINK_VERSION, ...edits.map(encodeEdit)].join('~');
}

/** Whether `edits` fit in a share link (else the link leaves them out). */
export function editsFitLink(edits: readonly Edit[]): boolean {
  return encodeEdits(edits).length <= MAX_EDITS_LINK_LENGTH;
}

function decodeEdit(item: string): Edit | string {
  const op = item.charAt(0);
  const raw = item.slice(1).split('.');
  const values: number[] = [];
  for (const text of raw) {
    if (!INT_RE.test(text)) return `"${text.slice(0, 24)}" is not a whole number of centimetres`;
    values.push(Number(text));
  }
  const n = values.length;
  switch (op) {
    case 'p': {
      if (n < 7 || (n - 4) % 3 !== 0)
        return `a paint stroke takes 4 numbers and x,y,z per point, got ${n} numbers`;
      const [r = 0, d = 0, s = 0, k = 0] = values;
      const points = undeltas(values.slice(4), 3) as EditPoint[];
      return {
        op: 'paint',
        points,
        radius: metres(r),
        density: d,
        segment: metres(s),
        kill: metres(k),
      };
    }
    case 'o': {
      if (n < 6 || n % 2 !== 0)
        return `a crown outline takes radius,height per point (at least 3), got ${n} numbers`;
      return { op: 'crown', outline: undeltas(values, 2) as [number, number][] };
    }
    case 'c': {
      if (n !== 3 && n !== 4) return `a cut takes 3 numbers (and a year), got ${n}`;
      const at = values.slice(0, 3).map(metres) as EditPoint;
      const year = values[3];
      return year === undefined ? { op: 'cut', at } : { op: 'cut', at, year };
    }
    case 'b':
      if (n !== 6) return `a bend takes 6 numbers, got ${n}`;
      return {
        op: 'bend',
        at: values.slice(0, 3).map(metres) as EditPoint,
        to: values.slice(3).map(metres) as EditPoint,
      };
    default:
      return `unknown op "${op}" (p = paint, o = crown outline, c = cut, b = bend)`;
  }
}

/**
 * Decodes an `e=` value strictly (see the module comment). Never throws; `messages` holds at
 * most one line, and `edits` is empty whenever it does.
 */
export function decodeEdits(value: string | null): { edits: Edit[]; messages: string[] } {
  if (value === null || value === '') return { edits: [], messages: [] };
  const fail = (why: string) => ({
    edits: [],
    messages: [
      `Ignored the edits in the link: ${why}. Import the edit list (Import edits…) instead.`,
    ],
  });
  if (value.length > MAX_EDITS_LINK_LENGTH) {
    return fail(`too long (${value.length} characters, limit ${MAX_EDITS_LINK_LENGTH})`);
  }
  const [version, ...items] = value.split('~');
  if (version !== EDITS_LINK_VERSION) {
    return fail(
      `unsupported version "${(version ?? '').slice(0, 24)}" (this app reads ${EDITS_LINK_VERSION})`,
    );
  }
  if (items.length > MAX_EDITS) return fail(`${items.length} edits, at most ${MAX_EDITS}`);
  const edits: Edit[] = [];
  for (const [i, item] of items.entries()) {
    const result = decodeEdit(item);
    if (typeof result === 'string') return fail(`e[${i}]: ${result}`);
    edits.push(result);
  }
  try {
    validateEdits(edits);
  } catch (error) {
    if (error instanceof EditsError) return fail(error.message);
    throw error;
  }
  return { edits: edits.map(quantizeEdit), messages: [] };
}
