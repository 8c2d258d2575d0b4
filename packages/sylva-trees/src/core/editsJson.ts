/**
 * The edit list's JSON, read as strictly as the core reads it
 * (`core-rs/sylva-core/src/params/edits/json.rs`): the document `{"version": 1, "edits": [...]}`
 * the app exports and imports (a bare array is accepted too), and the `"edits"` array of the
 * core's input. Unknown ops and fields, wrong types and counts past the limits throw an
 * [`EditsError`] naming the edit and field; the parsed list is then validated.
 */
import {
  checkCount,
  checkPoints,
  EDITS_VERSION,
  EditsError,
  MAX_OUTLINE_POINTS,
  MAX_STROKE_POINTS,
  validateEdits,
  type Edit,
  type EditPoint,
} from './edits';

type Json = Record<string, unknown>;

const FIELDS: Record<Edit['op'], readonly string[]> = {
  paint: ['op', 'points', 'radius', 'density', 'segment', 'kill'],
  crown: ['op', 'outline'],
  cut: ['op', 'at', 'year'],
  bend: ['op', 'at', 'to'],
};

function isRecord(value: unknown): value is Json {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

/** A JSON value for a message, cut to 40 characters. */
function short(v: unknown): string {
  const s = JSON.stringify(v) ?? String(v);
  const chars = Array.from(s);
  return chars.length > 40 ? `${chars.slice(0, 40).join('')}…` : s;
}

function cut32(text: string): string {
  return Array.from(text).slice(0, 32).join('');
}

function required(o: Json, key: string, field: string): unknown {
  if (!(key in o)) throw new EditsError(field, `${field} is missing`);
  return o[key];
}

function array(o: Json, key: string, field: string): unknown[] {
  const v = required(o, key, field);
  if (!Array.isArray(v)) throw new EditsError(field, `${field} must be an array of points`);
  return v;
}

function number(v: unknown, field: string): number {
  if (typeof v !== 'number') {
    throw new EditsError(field, `${field} must be a number, got ${short(v)}`);
  }
  return v;
}

function coords(v: unknown, field: string, n: 2 | 3): number[] {
  if (!Array.isArray(v) || v.length !== n) {
    throw new EditsError(field, `${field} must be an array of ${n} numbers, got ${short(v)}`);
  }
  return v.map((x, k) => number(x, `${field}[${k}]`));
}

const vec3 = (v: unknown, field: string) => coords(v, field, 3) as EditPoint;
const vec2 = (v: unknown, field: string) => coords(v, field, 2) as [number, number];

/** One edit `edits[i]` (structure only; ranges are checked by `validateEdits`). */
function parseEdit(i: number, item: unknown): Edit {
  const f = (name: string) => `edits[${i}].${name}`;
  if (!isRecord(item)) throw new EditsError(`edits[${i}]`, `edits[${i}] must be an object`);
  const op = typeof item.op === 'string' ? item.op : '';
  const allowed = (FIELDS as Record<string, readonly string[] | undefined>)[op];
  if (!allowed || !Object.hasOwn(FIELDS, op)) {
    throw new EditsError(
      f('op'),
      `${f('op')} is '${cut32(op)}': it must be "paint", "crown", "cut" or "bend"`,
    );
  }
  const unknown = Object.keys(item)
    .sort()
    .find((k) => !allowed.includes(k));
  if (unknown !== undefined) {
    const shown = cut32(unknown);
    throw new EditsError(
      f(shown),
      `${f(shown)} is not a field of a ${op} edit (${allowed.join(', ')})`,
    );
  }
  switch (op as Edit['op']) {
    case 'paint': {
      const items = array(item, 'points', f('points'));
      checkPoints(f('points'), items.length, MAX_STROKE_POINTS, 1);
      const points = items.map((v, k) => vec3(v, `${f('points')}[${k}]`));
      const scalar = (key: string) => number(required(item, key, f(key)), f(key));
      return {
        op: 'paint',
        points,
        radius: scalar('radius'),
        density: scalar('density'),
        segment: scalar('segment'),
        kill: scalar('kill'),
      };
    }
    case 'crown': {
      const items = array(item, 'outline', f('outline'));
      checkPoints(f('outline'), items.length, MAX_OUTLINE_POINTS, 3);
      return { op: 'crown', outline: items.map((v, k) => vec2(v, `${f('outline')}[${k}]`)) };
    }
    case 'cut': {
      const at = vec3(required(item, 'at', f('at')), f('at'));
      return 'year' in item
        ? { op: 'cut', at, year: number(item.year, f('year')) }
        : { op: 'cut', at };
    }
    case 'bend':
      return {
        op: 'bend',
        at: vec3(required(item, 'at', f('at')), f('at')),
        to: vec3(required(item, 'to', f('to')), f('to')),
      };
  }
}

/** Parses the value of `"edits"` (an array of edits) and validates it; throws [`EditsError`]. */
export function parseEditsValue(value: unknown): Edit[] {
  if (!Array.isArray(value)) throw new EditsError('edits', 'edits must be an array of edits');
  checkCount(value.length);
  const edits = value.map((item, i) => parseEdit(i, item));
  validateEdits(edits);
  return edits;
}

/**
 * Parses an edit list document `{"version": 1, "edits": [...]}` (or a bare array of edits);
 * throws [`EditsError`] naming what is wrong (invalid JSON included).
 */
export function parseEditsDocument(text: string): Edit[] {
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch (error) {
    const why = error instanceof Error ? error.message : String(error);
    throw new EditsError(
      'edits',
      `the edit list must be JSON like {"version": 1, "edits": [...]}: ${why}`,
    );
  }
  if (!isRecord(value)) return parseEditsValue(value);
  for (const key of Object.keys(value).sort()) {
    if (key !== 'version' && key !== 'edits') {
      const shown = cut32(key);
      throw new EditsError(shown, `'${shown}' is not a field of the edit list (version, edits)`);
    }
  }
  if (value.version !== EDITS_VERSION) {
    throw new EditsError(
      'version',
      `version must be ${EDITS_VERSION}, got ${JSON.stringify(value.version ?? null)}`,
    );
  }
  return parseEditsValue(value.edits ?? null);
}

/** The edits as plain JSON values (the core's `"edits"` array; copies, no extra fields). */
export function editsToCore(edits: readonly Edit[]): Record<string, unknown>[] {
  return edits.map((e) => {
    switch (e.op) {
      case 'paint': {
        const { points, radius, density, segment, kill } = e;
        return { op: 'paint', points, radius, density, segment, kill };
      }
      case 'crown':
        return { op: 'crown', outline: e.outline };
      case 'cut':
        return e.year === undefined
          ? { op: 'cut', at: e.at }
          : { op: 'cut', at: e.at, year: e.year };
      case 'bend':
        return { op: 'bend', at: e.at, to: e.to };
    }
  });
}

/** The edit list document the app exports (`sylva-edits.json`), pretty-printed. */
export function editsDocument(edits: readonly Edit[]): string {
  const lines = editsToCore(edits).map((e) => `    ${JSON.stringify(e)}`);
  const body = lines.length > 0 ? `\n${lines.join(',\n')}\n  ` : '';
  return `{\n  "version": ${EDITS_VERSION},\n  "edits": [${body}]\n}\n`;
}

/**
 * The core's input JSON object: the params, the growth volumes' `"volumes"` and the edits'
 * `"edits"`, each key only when its list is non-empty (so a tree without them is sent exactly
 * as before).
 */
export function coreInput(
  params: object,
  volumes: readonly Record<string, unknown>[] | undefined,
  edits: readonly Edit[] | undefined,
): Record<string, unknown> {
  return {
    ...params,
    ...(volumes?.length ? { volumes } : {}),
    ...(edits?.length ? { edits: editsToCore(edits) } : {}),
  };
}
