/** Share-URL codec: params ⇄ `v=1&id=value…` query strings (non-defaults only), with validation. */
import { defaultParams, displayValue, normalizeValue } from '../core/params';
import type { ParamSpec, Params } from '../core/types';

/** Current format version written as `v=`. */
export const FORMAT_VERSION = '1';
/** Longest query accepted when decoding (characters, without the leading `?`). */
export const MAX_QUERY_LENGTH = 4096;
/** Non-parameter query keys carried over when the URL is rewritten. */
export const KEPT_KEYS: readonly string[] = ['debug'];
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
  if (query.length > MAX_QUERY_LENGTH) {
    notices.add(
      `The share link is too long (${query.length} characters, limit ${MAX_QUERY_LENGTH}); loaded the defaults.`,
    );
    return { params, messages: notices.done(), hasParams: true };
  }
  const pairs = splitQuery(query, notices);
  const byId = new Map(registry.map((s) => [s.id, s]));
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
