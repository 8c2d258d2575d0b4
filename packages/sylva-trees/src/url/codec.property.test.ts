/**
 * Property tests (fast-check) of the share-URL codec over the real registry: decoding never
 * throws and only ever yields valid params, encoding round-trips, and junk is rejected with a
 * message naming the key. Runs `NUM_RUNS` cases per property.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { defaultParams, normalizeValue } from '../core/params';
import type { ParamSpec, Params } from '../core/types';
import { realRegistry } from '../testing/realWasm';
import {
  decodeQuery,
  encodeParams,
  MAX_MESSAGES,
  MAX_QUERY_LENGTH,
  parseValue,
  shown,
  type DecodeResult,
} from './codec';

const NUM_RUNS = Number(process.env.SYLVA_FC_RUNS ?? 1000);
const registry = realRegistry();
const ids = registry.map((s) => s.id);
const defaults = defaultParams(registry);
const byId = new Map<string, ParamSpec>(registry.map((s) => [s.id, s]));
const NUMBER_TEXT = /^[+-]?(\d+(\.\d*)?|\.\d+)(e[+-]?\d+)?$/i;
/** Control, format (bidi, zero-width), surrogate and private-use characters. */
const UNSHOWABLE = /\p{C}/u;

/** Whether a number read from a link is acceptable for `spec` (-0 reads as 0). */
function acceptable(spec: ParamSpec, value: number): boolean {
  return validFor(spec, value === 0 ? 0 : value);
}

/** Whether `value` is a value the generator accepts for `spec` (and normalised: never -0). */
function validFor(spec: ParamSpec, value: number): boolean {
  if (!Number.isFinite(value) || value < spec.min || value > spec.max) return false;
  if (spec.kind !== 'float' && !Number.isInteger(value)) return false;
  if (spec.kind === 'enum' && value >= (spec.options?.length ?? 0)) return false;
  return !Object.is(value, -0);
}

function tryDecode(text: string): string | null {
  try {
    return decodeURIComponent(text.replace(/\+/g, ' '));
  } catch {
    return null;
  }
}

/** The invariants of every decode result, whatever the input. */
function expectWellFormed(result: DecodeResult): void {
  const keys = Object.keys(result.params);
  const bad = registry
    .filter((spec) => !validFor(spec, result.params[spec.id] ?? Number.NaN))
    .map((spec) => `${spec.id}=${result.params[spec.id]}`);
  if (keys.length !== ids.length) bad.push(`keys: ${keys.join(',')}`);
  for (const message of result.messages) {
    if (typeof message !== 'string' || message.length >= 400 || UNSHOWABLE.test(message)) {
      bad.push(`message: ${JSON.stringify(message)}`);
    }
  }
  if (result.messages.length > MAX_MESSAGES + 1) bad.push(`${result.messages.length} messages`);
  expect(bad).toEqual([]);
}

/** Any integer in [lo, hi] (the seed's range passes 2^31, beyond `fc.integer`). */
function intBetween(lo: number, hi: number): fc.Arbitrary<number> {
  return fc.bigInt({ min: BigInt(lo), max: BigInt(hi) }).map(Number);
}

/** A random valid value for a spec: bounds, default, grid values and arbitrary doubles. */
function validValue(spec: ParamSpec): fc.Arbitrary<number> {
  if (spec.kind === 'enum') {
    return intBetween(0, Math.min(spec.max, (spec.options?.length ?? 1) - 1));
  }
  if (spec.kind !== 'float') {
    return fc.oneof(
      fc.constantFrom(spec.min, spec.max, spec.default),
      intBetween(Math.ceil(spec.min), Math.floor(spec.max)),
    );
  }
  return fc.oneof(
    fc.constantFrom(spec.min, spec.max, spec.default),
    fc.double({ min: spec.min, max: spec.max, noNaN: true }).map((v) => (v === 0 ? 0 : v)),
    fc
      .integer({ min: 0, max: Math.round((spec.max - spec.min) / spec.step) })
      .map((k) => Math.min(spec.max, Number((spec.min + k * spec.step).toFixed(6)))),
  );
}

/** Random valid params: defaults with some entries replaced. */
const validParams: fc.Arbitrary<Params> = fc
  .array(
    fc
      .constantFrom(...registry)
      .chain((spec) => validValue(spec).map((v) => [spec.id, v] as const)),
    { maxLength: 20 },
  )
  .map((entries) => {
    const params: Params = { ...defaults };
    for (const [id, v] of entries) params[id] = v;
    return params;
  });

/** Text that is not a plain decimal number (words, hex, NaN, spaces, scripts, unicode digits). */
const junkText: fc.Arbitrary<string> = fc
  .oneof(
    fc.string({ unit: 'binary', maxLength: 40 }),
    fc.constantFrom(
      'NaN',
      'Infinity',
      '-Infinity',
      '0x10',
      '1_000',
      '1,5',
      ' 5',
      '5 ',
      '\t1',
      '1e',
      '--1',
      '.',
      '',
      '٣',
      '１',
      'javascript:alert(1)',
      '<script>alert(1)</script>',
      '"><img src=x onerror=alert(1)>',
      '${alert(1)}',
      'constructor',
      '__proto__',
      '1\u0000',
      '\u202e1',
    ),
  )
  .filter((t) => !NUMBER_TEXT.test(t));

/** One query entry: a registry key, `v`, or junk, with any value, maybe %-encoded. */
const entry: fc.Arbitrary<string> = fc
  .tuple(
    fc.oneof(
      { weight: 6, arbitrary: fc.constantFrom(...ids) },
      { weight: 1, arbitrary: fc.constantFrom('v', '', '__proto__', 'constructor', 'debug') },
      { weight: 1, arbitrary: fc.string({ unit: 'binary', maxLength: 12 }) },
    ),
    fc.oneof(
      fc.double().map(String),
      fc.integer().map(String),
      fc.bigInt({ min: -(2n ** 40n), max: 2n ** 40n }).map(String),
      fc.constantFrom('1', '-0', '1e309', '5e-324', '0.1', '4294967296'),
      junkText,
    ),
    fc.boolean(),
    fc.boolean(),
  )
  .map(([key, value, encode, hasEq]) => {
    const k = encode ? encodeURIComponent(key) : key;
    const v = encode ? encodeURIComponent(value) : value;
    return hasEq ? `${k}=${v}` : k;
  });

describe('codec properties (fast-check)', () => {
  it('decodeQuery never throws on arbitrary text, and always yields valid params', () => {
    fc.assert(
      fc.property(fc.string({ unit: 'binary', maxLength: 300 }), (text) => {
        expectWellFormed(decodeQuery(registry, text));
        expectWellFormed(decodeQuery(registry, `?${text}`));
      }),
      { numRuns: NUM_RUNS },
    );
  });

  it('decodeQuery never throws on lone surrogates, raw % and random bytes', () => {
    const piece = fc.oneof(
      fc.constantFrom('%', '%E0%A4%A', '%ZZ', '%ED%A0%80', '%00', '%FF', '&', '=', '+', '#'),
      fc.string({ unit: 'binary-ascii', maxLength: 8 }),
      fc.integer({ min: 0xd800, max: 0xdfff }).map((c) => String.fromCharCode(c)),
    );
    fc.assert(
      fc.property(fc.array(piece, { maxLength: 40 }), (pieces) => {
        expectWellFormed(decodeQuery(registry, `?v=1&${pieces.join('')}`));
      }),
      { numRuns: NUM_RUNS },
    );
  });

  it('decodeQuery on structured hostile queries: valid params, first value of a key wins', () => {
    fc.assert(
      fc.property(fc.array(entry, { maxLength: 30 }), (entries) => {
        const query = `?${entries.join('&')}`;
        const result = decodeQuery(registry, query);
        expectWellFormed(result);
        if (query.length > MAX_QUERY_LENGTH) return;
        if (/(^|&)v=(?!1(&|$))/.test(query.slice(1)) || /(^|&)v(&|$)/.test(query.slice(1))) return;
        // The first occurrence of a key decides its value: a plain in-range number is taken
        // (normalised), anything else leaves the default.
        const firsts = new Map<string, string | null>();
        for (const piece of query.slice(1).split('&')) {
          const eq = piece.indexOf('=');
          const key = tryDecode(eq < 0 ? piece : piece.slice(0, eq));
          if (key === null || firsts.has(key)) continue;
          firsts.set(key, tryDecode(eq < 0 ? '' : piece.slice(eq + 1)));
        }
        for (const spec of registry) {
          const raw = firsts.get(spec.id);
          const value = raw === undefined || raw === null ? Number.NaN : Number(raw);
          const taken =
            raw !== undefined && raw !== null && NUMBER_TEXT.test(raw) && acceptable(spec, value);
          const expected = taken ? normalizeValue(spec, value) : spec.default;
          expect(result.params[spec.id], `${spec.id} from ${JSON.stringify(raw)}`).toBe(expected);
        }
      }),
      { numRuns: NUM_RUNS },
    );
  });

  it('encode then decode gives back the normalised params, without messages', () => {
    fc.assert(
      fc.property(validParams, (params) => {
        const query = encodeParams(registry, params);
        expect(query.startsWith('v=1')).toBe(true);
        expect(query.length).toBeLessThan(MAX_QUERY_LENGTH);
        const decoded = decodeQuery(registry, `?${query}`);
        expect(decoded.messages).toEqual([]);
        for (const spec of registry) {
          const expected = normalizeValue(spec, params[spec.id] ?? spec.default);
          expect(decoded.params[spec.id], spec.id).toBe(expected);
        }
        // And encoding is a fixed point after one round.
        expect(encodeParams(registry, decoded.params)).toBe(query);
      }),
      { numRuns: NUM_RUNS },
    );
  });

  it('decode(encode(decode(q))) keeps what was accepted from any query', () => {
    fc.assert(
      fc.property(fc.array(entry, { maxLength: 20 }), (entries) => {
        const first = decodeQuery(registry, entries.join('&'));
        const again = decodeQuery(registry, encodeParams(registry, first.params));
        expect(again.messages).toEqual([]);
        expect(again.params).toEqual(first.params);
      }),
      { numRuns: NUM_RUNS },
    );
  });

  it('junk values are rejected: default kept, message names the key, junk shown inert', () => {
    fc.assert(
      fc.property(fc.constantFrom(...registry), junkText, (spec, junk) => {
        const result = decodeQuery(registry, `?v=1&${spec.id}=${encodeURIComponent(junk)}`);
        expect(result.params[spec.id]).toBe(spec.default);
        expect(result.messages).toHaveLength(1);
        expect(result.messages[0]).toContain(`"${spec.id}"`);
        expect(typeof parseValue(spec, junk)).toBe('string');
        expectWellFormed(result);
      }),
      { numRuns: NUM_RUNS },
    );
  });

  it('out-of-range and fractional numbers are rejected for their key', () => {
    const bad = fc.constantFrom(...registry).chain((spec) =>
      fc
        .oneof(
          fc.double({ noNaN: true, noDefaultInfinity: true }),
          fc.double({ min: spec.max, max: spec.max * 10 + 10, noNaN: true }),
          fc.integer({ min: -1_000_000, max: -1 }),
          fc.double({ min: 0.01, max: 0.99, noNaN: true }).map((f) => Math.floor(spec.max) - f),
        )
        .filter((v) => !acceptable(spec, v))
        .filter((v) => !(spec.kind === 'float' && v >= spec.min && v <= spec.max))
        .map((v) => [spec, v] as const),
    );
    fc.assert(
      fc.property(bad, ([spec, v]) => {
        const result = decodeQuery(registry, `?v=1&${spec.id}=${String(v)}`);
        expect(result.params[spec.id]).toBe(spec.default);
        expect(result.messages.join(' ')).toContain(`"${spec.id}"`);
      }),
      { numRuns: NUM_RUNS },
    );
  });

  it('shown() never returns invisible or direction-changing characters, and stays short', () => {
    fc.assert(
      fc.property(fc.string({ unit: 'binary', maxLength: 200 }), (text) => {
        const out = shown(text);
        expect(UNSHOWABLE.test(out)).toBe(false);
        expect(Array.from(out).length).toBeLessThanOrEqual(25);
      }),
      { numRuns: NUM_RUNS },
    );
  });

  it('hostile keys never touch Object.prototype or add params', () => {
    const before = Object.getOwnPropertyNames(Object.prototype).sort();
    const result = decodeQuery(
      registry,
      '?v=1&__proto__=1&constructor=2&prototype=3&toString=4&__proto__%5Bx%5D=5&hasOwnProperty=6',
    );
    expect(Object.getOwnPropertyNames(Object.prototype).sort()).toEqual(before);
    expect(result.params).toEqual(defaults);
    expect(Object.getPrototypeOf(result.params)).toBe(Object.prototype);
    expect(byId.has('__proto__')).toBe(false);
  });
});
