/** Share-URL codec: params ⇄ `v=1&id=value…` query strings (non-defaults only), with validation. */
import { defaultParams, displayValue, normalizeValue } from '../core/params';
import type { ParamSpec, Params, VolumeGroup, VolumeKind, VolumePrimitive } from '../core/types';
import { CENTRE_MAX, MAX_VOLUMES, SIZE_MAX, SIZE_MIN } from '../core/volumes';
import { EDITS_KEY } from './editsCodec';

/** Current format version written as `v=`. */
export const FORMAT_VERSION = '1';
/**
 * Longest query accepted when decoding (characters, without the leading `?`), not counting the
 * edits' `e=` entry, which has its own limit (`MAX_EDITS_LINK_LENGTH`).
 */
export const MAX_QUERY_LENGTH = 4096;
/** Non-parameter query keys carried over when the URL is rewritten. */
export const KEPT_KEYS: readonly string[] = ['debug', 'vol', EDITS_KEY, 'aa', 'forest'];
/** Most notices one decode reports; the rest are summed up in one more line. */
export const MAX_MESSAGES = 6;

/** Outcome of decoding a query: the params to use plus human-readable notices. */
export interface DecodeResult {
  params: Params;
  messages: string[];
  /** True when the query carried a version or any parameter key. */
  hasParams: boolean;
}

/** A plain decimal number: ASCII digits only, no whitespace, hex, `Infinity` or `NaN`. */
const NUMBER_RE = /^[+-]?(\d+(\.\d*)?|\.\d+)(e[+-]?\d+)?$/i;
/** Control, format (bidi overrides, zero-width), surrogate and private-use characters. */
const UNSHOWABLE_RE = /\p{C}/gu;
const SHOWN_VALUE_MAX = 24;

/** Formats a value so that `Number(text)` gives back exactly the same number. */
export function formatNumber(value: number): string {
  if (Object.is(value, -0)) return '0';
  return String(value);
}

/** Encodes only the non-default values (after normalisation), prefixed by the version. */
export function encodeParams(registry: readonly ParamSpec[], params: Params): string {
  const parts = [`v=${FORMAT_VERSION}`];
  for (const spec of registry) {
    const raw = params[spec.id];
    if (raw === undefined) continue;
    const value = normalizeValue(spec, raw);
    if (value === spec.default) continue;
    parts.push(`${encodeURIComponent(spec.id)}=${formatNumber(value)}`);
  }
  return parts.join('&');
}

/**
 * Shortens user-provided text for display in a message: at most 24 characters, invisible and
 * direction-changing characters shown as `?` (it is rendered as text, never as HTML).
 */
export function shown(text: string): string {
  const chars = Array.from(text.slice(0, SHOWN_VALUE_MAX * 2));
  const clean = chars.slice(0, SHOWN_VALUE_MAX).join('').replace(UNSHOWABLE_RE, '?');
  return chars.length > SHOWN_VALUE_MAX || text.length > SHOWN_VALUE_MAX * 2 ? `${clean}…` : clean;
}

function rangeText(spec: ParamSpec): string {
  if (spec.kind === 'bool') return '0 or 1';
  if (spec.kind === 'enum' && spec.options) {
    return `an option index 0–${spec.options.length - 1}`;
  }
  const kind = spec.kind === 'int' ? 'an integer' : 'a number';
  return `${kind} in ${formatNumber(spec.min)}–${formatNumber(spec.max)}`;
}

/** Validates one raw query value against its spec; returns the value or a reason. */
export function parseValue(spec: ParamSpec, raw: string): number | string {
  if (!NUMBER_RE.test(raw)) return `"${shown(raw)}" is not a number`;
  const value = Number(raw);
  if (!Number.isFinite(value)) return `"${shown(raw)}" is not a finite number`;
  const integral = spec.kind !== 'float';
  if (integral && !Number.isInteger(value)) return `"${shown(raw)}" is not an integer`;
  if (value < spec.min || value > spec.max) return `"${shown(raw)}" is out of range`;
  if (spec.kind === 'enum' && spec.options && value >= spec.options.length) {
    return `"${shown(raw)}" is not a valid option`;
  }
  return normalizeValue(spec, value);
}

function safeDecode(text: string): string | null {
  try {
    return decodeURIComponent(text.replace(/\+/g, ' '));
  } catch {
    return null;
  }
}

/** Splits a query into decoded [key, value] pairs; undecodable pieces are reported. */
function splitQuery(query: string, notices: Notices): [string, string | null][] {
  const pairs: [string, string | null][] = [];
  for (const piece of query.split('&')) {
    if (piece === '') continue;
    const eq = piece.indexOf('=');
    const rawKey = eq < 0 ? piece : piece.slice(0, eq);
    const rawValue = eq < 0 ? '' : piece.slice(eq + 1);
    const key = safeDecode(rawKey);
    if (key === null) {
      notices.add(`Ignored a malformed share-link entry "${shown(rawKey)}" (bad %-encoding).`);
      continue;
    }
    pairs.push([key, safeDecode(rawValue)]);
  }
  return pairs;
}

/** Collects notices, keeping the first `MAX_MESSAGES` and counting the rest. */
class Notices {
  readonly lines: string[] = [];
  private dropped = 0;

  add(line: string): void {
    if (this.lines.length < MAX_MESSAGES) this.lines.push(line);
    else this.dropped++;
  }

  done(): string[] {
    if (this.dropped > 0) {
      const s = this.dropped === 1 ? '' : 's';
      this.lines.push(`…and ${this.dropped} more problem${s} in the share link (ignored).`);
    }
    return this.lines;
  }
}

/**
 * Decodes a share query (with or without the leading `?`). Unknown keys are ignored; a bad
 * value falls back to that param's default with a message naming the key; a key given twice
 * keeps its first value; an unsupported version or an over-long query yields all defaults
 * with a message. Never throws; the values are only ever parsed as numbers.
 */
export function decodeQuery(registry: readonly ParamSpec[], search: string): DecodeResult {
  const query = search.startsWith('?') ? search.slice(1) : search;
  const params = defaultParams(registry);
  const notices = new Notices();
  const measured = withoutEdits(query).length;
  if (measured > MAX_QUERY_LENGTH) {
    notices.add(
      `The share link is too long (${measured} characters, limit ${MAX_QUERY_LENGTH}); loaded the defaults.`,
    );
    return { params, messages: notices.done(), hasParams: true };
  }
  const pairs = splitQuery(query, notices);
  const byId = new Map<string, ParamSpec>(registry.map((s) => [s.id, s]));
  const versions = pairs.filter(([k]) => k === 'v');
  const version = versions[0];
  const hasParams = version !== undefined || pairs.some(([k]) => byId.has(k));
  if (version !== undefined && version[1] !== FORMAT_VERSION) {
    notices.add(
      `Unsupported share-link version "${shown(version[1] ?? '')}" (this app reads v=${FORMAT_VERSION}); loaded the defaults.`,
    );
    return { params, messages: notices.done(), hasParams };
  }
  if (versions.some(([, v]) => v !== FORMAT_VERSION)) {
    notices.add(`Ignored a repeated share-link version; read it as v=${FORMAT_VERSION}.`);
  }
  const seen = new Set<string>();
  for (const [key, rawValue] of pairs) {
    const spec = byId.get(key);
    if (!spec) continue;
    if (seen.has(spec.id)) {
      notices.add(`Ignored a repeated "${spec.id}" in the link; kept its first value.`);
      continue;
    }
    seen.add(spec.id);
    const result = rawValue === null ? 'the value has bad %-encoding' : parseValue(spec, rawValue);
    if (typeof result === 'number') {
      params[spec.id] = result;
    } else {
      notices.add(
        `Ignored "${spec.id}" from the link: ${result} (expected ${rangeText(spec)}); using the default ${displayValue(spec, spec.default)}.`,
      );
    }
  }
  return { params, messages: notices.done(), hasParams };
}

/** `query` without its `e=` entries (they are limited on their own). */
function withoutEdits(query: string): string {
  if (!query.includes(`${EDITS_KEY}=`)) return query;
  return query
    .split('&')
    .filter((piece) => piece.split('=', 1)[0] !== EDITS_KEY)
    .join('&');
}

/** Rebuilds a page query: the encoded params plus any kept non-param keys (e.g. `debug`). */
export function buildSearch(
  registry: readonly ParamSpec[],
  params: Params,
  currentSearch: string,
): string {
  const kept = new URLSearchParams(currentSearch);
  const extra: string[] = [];
  for (const key of KEPT_KEYS) {
    const value = kept.get(key);
    if (value !== null) extra.push(`${key}=${encodeURIComponent(value)}`);
  }
  return `?${[encodeParams(registry, params), ...extra].join('&')}`;
}

/** Query key of the growth volume primitives. */
export const VOLUMES_KEY = 'vol';
/** Version prefix of the `vol=` value. */
export const VOLUMES_VERSION = '1';
/** Longest `vol=` value accepted (characters). */
export const MAX_VOLUMES_LENGTH = 1500;

const KIND_CODES: Record<VolumeKind, string> = { sphere: 's', box: 'b', cylinder: 'c' };
const GROUP_CODES: Record<VolumeGroup, string> = { crown: 'c', shadow: 's', exclusion: 'x' };
/** Numbers after the centre: sphere r; box w, h, d; cylinder r, h. */
const SIZE_COUNT: Record<VolumeKind, number> = { sphere: 1, box: 3, cylinder: 2 };

function sizeNumbers(v: VolumePrimitive): number[] {
  if (v.kind === 'sphere') return [v.size[0]];
  if (v.kind === 'cylinder') return [v.size[0], v.size[1]];
  return [...v.size];
}

/**
 * Encodes primitives as the compact `vol=` value: `1;s:c:x,y,z,r;b:x:x,y,z,w,h,d;c:s:x,y,z,r,h`
 * (version, then per primitive its kind s/b/c, group c(rown)/s(hadow)/x (exclusion) and numbers).
 * Empty list: empty string (no key).
 */
export function encodeVolumes(volumes: readonly VolumePrimitive[]): string {
  if (volumes.length === 0) return '';
  const items = volumes.map(
    (v) =>
      `${KIND_CODES[v.kind]}:${GROUP_CODES[v.group]}:${[...v.centre, ...sizeNumbers(v)].map(formatNumber).join(',')}`,
  );
  return [VOLUMES_VERSION, ...items].join(';');
}

function decodeVolume(item: string): VolumePrimitive | string {
  const parts = item.split(':');
  if (parts.length !== 3) return `"${shown(item)}" is not kind:group:numbers`;
  const [k, g, nums] = parts as [string, string, string];
  const kind = (Object.keys(KIND_CODES) as VolumeKind[]).find((x) => KIND_CODES[x] === k);
  if (!kind) return `unknown kind "${shown(k)}" (s = sphere, b = box, c = cylinder)`;
  const group = (Object.keys(GROUP_CODES) as VolumeGroup[]).find((x) => GROUP_CODES[x] === g);
  if (!group) return `unknown group "${shown(g)}" (c = crown, s = shadow, x = exclusion)`;
  const raw = nums.split(',');
  const want = 3 + SIZE_COUNT[kind];
  if (raw.length !== want) return `a ${kind} takes ${want} numbers, got ${raw.length}`;
  const values: number[] = [];
  for (const text of raw) {
    if (!NUMBER_RE.test(text)) return `"${shown(text)}" is not a number`;
    const value = Number(text);
    if (!Number.isFinite(value)) return `"${shown(text)}" is not a finite number`;
    values.push(value);
  }
  const centre = values.slice(0, 3) as [number, number, number];
  if (centre.some((c) => Math.abs(c) > CENTRE_MAX)) {
    return `a centre coordinate is outside -${CENTRE_MAX}–${CENTRE_MAX} m`;
  }
  const sizes = values.slice(3);
  if (sizes.some((x) => x < SIZE_MIN || x > SIZE_MAX)) {
    return `a size is outside ${SIZE_MIN}–${SIZE_MAX} m`;
  }
  const [a = 0, b = 0, c = 0] = sizes;
  const size: [number, number, number] =
    kind === 'sphere' ? [a, a, a] : kind === 'cylinder' ? [a, b, a] : [a, b, c];
  return { kind, group, centre, size };
}

/**
 * Decodes a `vol=` value strictly: wrong version or over-long value → no primitives; a bad
 * primitive is skipped with a message naming it (`vol[2]`); at most 32 are kept. Never throws.
 */
export function decodeVolumes(value: string | null): {
  volumes: VolumePrimitive[];
  messages: string[];
} {
  const notices = new Notices();
  const volumes: VolumePrimitive[] = [];
  if (value === null || value === '') return { volumes, messages: [] };
  if (value.length > MAX_VOLUMES_LENGTH) {
    notices.add(
      `Ignored the volumes in the link: too long (${value.length} characters, limit ${MAX_VOLUMES_LENGTH}).`,
    );
    return { volumes, messages: notices.done() };
  }
  const [version, ...items] = value.split(';');
  if (version !== VOLUMES_VERSION) {
    notices.add(
      `Ignored the volumes in the link: unsupported version "${shown(version ?? '')}" (this app reads ${VOLUMES_VERSION}).`,
    );
    return { volumes, messages: notices.done() };
  }
  items.forEach((item, i) => {
    const result = decodeVolume(item);
    if (typeof result === 'string') {
      notices.add(`Ignored vol[${i}] from the link: ${result}.`);
    } else if (volumes.length >= MAX_VOLUMES) {
      notices.add(`Ignored vol[${i}] from the link: at most ${MAX_VOLUMES} primitives.`);
    } else {
      volumes.push(result);
    }
  });
  return { volumes, messages: notices.done() };
}
