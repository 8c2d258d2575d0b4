/** URL codec tests over the real registry (loaded from the wasm module in Node). */
import { describe, expect, it } from 'vitest';
import { applyPreset, defaultParams, snapToStep } from '../core/params';
import type { ParamId, ParamSpec, Params } from '../core/types';
import { realPresets, realRegistry } from '../testing/realWasm';
import {
  buildSearch,
  decodeQuery,
  encodeParams,
  formatNumber,
  MAX_MESSAGES,
  MAX_QUERY_LENGTH,
} from './codec';

const registry = realRegistry();
const defaults = defaultParams(registry);
const spec = (id: string): ParamSpec => {
  const s = registry.find((p) => p.id === id);
  if (!s) throw new Error(`no param ${id}`);
  return s;
};
const firstOf = (kind: ParamSpec['kind']): ParamSpec | undefined =>
  registry.find((s) => s.kind === kind && s.id !== 'seed');

/** Deterministic pseudo-random numbers for the round-trip sweep. */
function lcg(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (Math.imul(state, 1664525) + 1013904223) >>> 0;
    return state / 2 ** 32;
  };
}

/** A random valid value for a spec, as a slider would produce it. */
function randomValue(s: ParamSpec, random: () => number): number {
  return snapToStep(s, s.min + random() * (s.max - s.min));
}

describe('registry sanity', () => {
  it('has the params the app relies on', () => {
    expect(spec('seed').kind).toBe('int');
    expect(spec('scale').kind).toBe('float');
    expect(spec('l1_length').kind).toBe('float');
  });
});

describe('encodeParams', () => {
  it('encodes only the version for all defaults', () => {
    expect(encodeParams(registry, defaults)).toBe('v=1');
  });

  it('encodes only non-default values, keyed by id', () => {
    const params = { ...defaults, seed: 7, l1_length: 0.35 };
    expect(encodeParams(registry, params)).toBe('v=1&seed=7&l1_length=0.35');
  });

  it('snaps float noise so 0.1 + 0.2 style values stay short', () => {
    const params = { ...defaults, l1_length: 0.1 + 0.2 + 0.05 };
    expect(encodeParams(registry, params)).toBe('v=1&l1_length=0.35');
  });

  it('treats a value equal to an f32-noisy default as default', () => {
    const s = spec('l1_length');
    const onGrid = snapToStep(s, Number(s.default.toFixed(2)));
    expect(encodeParams(registry, { ...defaults, l1_length: onGrid })).toBe('v=1');
  });

  it('never writes -0, NaN or exponent-less garbage', () => {
    const s = firstOf('float');
    if (!s) return;
    expect(formatNumber(-0)).toBe('0');
    expect(formatNumber(1e21)).toBe('1e+21');
  });
});

describe('round trip', () => {
  it('decode(encode(p)) === p for random slider values of every param', () => {
    const random = lcg(42);
    for (let trial = 0; trial < 200; trial++) {
      const params: Params = { ...defaults };
      for (const s of registry) if (random() < 0.5) params[s.id] = randomValue(s, random);
      const query = encodeParams(registry, params);
      const decoded = decodeQuery(registry, `?${query}`);
      expect(decoded.messages).toEqual([]);
      for (const s of registry) expect(decoded.params[s.id], s.id).toBe(params[s.id]);
      expect(encodeParams(registry, decoded.params)).toBe(query);
    }
  });

  it('round-trips every bound and the default of every param', () => {
    for (const s of registry) {
      for (const value of [s.min, s.max, s.default]) {
        const params = { ...defaults, [s.id]: value };
        const decoded = decodeQuery(registry, encodeParams(registry, params));
        expect(decoded.params[s.id], `${s.id}=${value}`).toBe(value);
      }
    }
  });

  it('round-trips every preset exactly', () => {
    for (const preset of realPresets()) {
      const params = applyPreset(registry, preset);
      const decoded = decodeQuery(registry, encodeParams(registry, params));
      expect(decoded.params).toEqual(params);
    }
  });

  it('carries the season and the phenology of a maple in October', () => {
    const umbrella = realPresets().find((p) => p.name === 'umbrella');
    if (!umbrella) throw new Error('no umbrella preset');
    const params = { ...applyPreset(registry, umbrella), season: 10.5 };
    expect(params.leaf_phenology).toBe(spec('leaf_phenology').options?.indexOf('Maple'));
    const query = encodeParams(registry, params);
    expect(query).toContain('season=10.5');
    expect(query).toContain('leaf_phenology=1');
    expect(decodeQuery(registry, `?${query}`).params).toEqual(params);
    // July, the default, stays out of the link.
    expect(encodeParams(registry, { ...params, season: 7 })).not.toContain('season');
  });

  it('keeps the debug flag when rebuilding the page query', () => {
    const search = buildSearch(registry, { ...defaults, seed: 3 }, '?debug=1&seed=9');
    expect(search).toBe('?v=1&seed=3&debug=1');
    // The antialiasing choice (aa=1/0) survives edits and reloads too.
    expect(buildSearch(registry, defaults, '?aa=1&seed=9')).toBe('?v=1&aa=1');
  });
});

describe('decodeQuery with malformed input', () => {
  const expectFallback = (query: string, id: ParamId) => {
    const result = decodeQuery(registry, query);
    expect(result.params[id]).toBe(spec(id).default);
    expect(result.messages.length).toBeGreaterThan(0);
    expect(result.messages.some((m) => m.includes(`"${id}"`))).toBe(true);
    return result;
  };

  it('empty query: defaults, no messages, no params', () => {
    const result = decodeQuery(registry, '');
    expect(result).toEqual({ params: defaults, messages: [], hasParams: false });
  });

  it('NaN, Infinity, 1e999 and text fall back to the default with a message naming the key', () => {
    expectFallback('?v=1&l1_length=NaN', 'l1_length');
    expectFallback('?v=1&l1_length=Infinity', 'l1_length');
    expectFallback('?v=1&scale=1e999', 'scale');
    expectFallback('?v=1&scale=abc', 'scale');
    expectFallback('?v=1&scale=', 'scale');
    expectFallback('?v=1&scale=0x10', 'scale');
  });

  it('the remaining valid values still apply', () => {
    const result = expectFallback('?v=1&scale=abc&seed=7&l1_length=0.35', 'scale');
    expect(result.params.seed).toBe(7);
    expect(result.params.l1_length).toBe(0.35);
    expect(result.messages).toHaveLength(1);
  });

  it('out-of-range and negative counts fall back', () => {
    const s = spec('scale');
    expectFallback(`?v=1&scale=${s.max * 10}`, 'scale');
    const count = registry.find((p) => p.kind === 'int' && p.min >= 0 && p.id !== 'seed');
    if (count) expectFallback(`?v=1&${count.id}=-3`, count.id);
  });

  it('non-integer values for int params fall back', () => {
    expectFallback('?v=1&seed=1.5', 'seed');
    const count = registry.find((p) => p.kind === 'int' && p.id !== 'seed');
    if (count) expectFallback(`?v=1&${count.id}=2.5`, count.id);
  });

  it('bool and enum values are validated', () => {
    const b = firstOf('bool');
    if (b) expectFallback(`?v=1&${b.id}=2`, b.id);
    const e = firstOf('enum');
    if (e) expectFallback(`?v=1&${e.id}=${(e.options?.length ?? 0) + 5}`, e.id);
  });

  it('an unsupported version gives a message and all defaults', () => {
    const result = decodeQuery(registry, '?v=2&seed=7');
    expect(result.params).toEqual(defaults);
    expect(result.messages.join(' ')).toMatch(/version/i);
  });

  it('unknown keys are ignored silently', () => {
    const result = decodeQuery(registry, '?v=1&bogus=1&debug=1&seed=5');
    expect(result.messages).toEqual([]);
    expect(result.params.seed).toBe(5);
  });

  it('a 10 kB value is rejected with a message and defaults', () => {
    const result = decodeQuery(registry, `?v=1&seed=${'9'.repeat(10_000)}`);
    expect(result.params).toEqual(defaults);
    expect(result.messages.join(' ')).toMatch(/too long/);
    expect(MAX_QUERY_LENGTH).toBeLessThan(10_000);
  });

  it('a long-but-allowed garbage value is reported shortened', () => {
    const result = expectFallback(`?v=1&scale=${'x'.repeat(2000)}`, 'scale');
    expect(result.messages[0]?.length ?? 0).toBeLessThan(300);
  });

  it('<script> fragments are treated as bad values, and reported as inert text', () => {
    const result = expectFallback(
      `?v=1&scale=${encodeURIComponent('<script>alert(1)</script>')}`,
      'scale',
    );
    expect(result.params.scale).toBe(spec('scale').default);
    const keyScript = decodeQuery(registry, '?v=1&%3Cscript%3E=1');
    expect(keyScript.params).toEqual(defaults);
  });

  it('broken percent-encoding in a value or key gives a message, not an exception', () => {
    expectFallback('?v=1&scale=%E0%A4%A', 'scale');
    expectFallback('?v=1&scale=%ZZ', 'scale');
    const badKey = decodeQuery(registry, '?v=1&%E0%A4%A=1&seed=4');
    expect(badKey.params.seed).toBe(4);
    expect(badKey.messages).toHaveLength(1);
  });

  it('accepts a query with or without the leading ?', () => {
    expect(decodeQuery(registry, 'v=1&seed=3').params.seed).toBe(3);
    expect(decodeQuery(registry, '?v=1&seed=3').params.seed).toBe(3);
  });
});

describe('strict parsing of hostile links', () => {
  it('whitespace around a number is junk, not trimmed away', () => {
    for (const value of ['%205', '5%20', '%095', '5%0A', '5%C2%A0', '+5']) {
      const result = decodeQuery(registry, `?v=1&seed=${value}`);
      expect(result.params.seed, value).toBe(spec('seed').default);
      expect(result.messages.join(' '), value).toContain('"seed"');
    }
  });

  it('a repeated key keeps its first value and says so', () => {
    const result = decodeQuery(registry, '?v=1&seed=3&seed=4&seed=abc');
    expect(result.params.seed).toBe(3);
    expect(result.messages).toHaveLength(2);
    expect(result.messages[0]).toMatch(/repeated "seed".*first value/);
    const firstBad = decodeQuery(registry, '?v=1&seed=abc&seed=4');
    expect(firstBad.params.seed).toBe(spec('seed').default);
  });

  it('a repeated version is read once; a second, different one is reported', () => {
    expect(decodeQuery(registry, '?v=1&v=1&seed=3').messages).toEqual([]);
    const mixed = decodeQuery(registry, '?v=1&v=2&seed=3');
    expect(mixed.params.seed).toBe(3);
    expect(mixed.messages.join(' ')).toMatch(/repeated share-link version/);
    expect(decodeQuery(registry, '?v=2&v=1&seed=3').params).toEqual(defaults);
    expect(decodeQuery(registry, '?v&seed=3').params).toEqual(defaults);
    expect(decodeQuery(registry, '?v=1.0&seed=3').params).toEqual(defaults);
  });

  it(`reports at most ${MAX_MESSAGES} problems, then sums up the rest`, () => {
    const query = registry
      .slice(0, 20)
      .map((s) => `${s.id}=x`)
      .join('&');
    const result = decodeQuery(registry, `?v=1&${query}`);
    expect(result.messages).toHaveLength(MAX_MESSAGES + 1);
    expect(result.messages[MAX_MESSAGES]).toBe(
      `…and ${20 - MAX_MESSAGES} more problems in the share link (ignored).`,
    );
    expect(result.params).toEqual(defaults);
  });

  it('control, null, zero-width and bidi characters are shown as ?', () => {
    const result = decodeQuery(registry, '?v=1&scale=%00%E2%80%AEabc%E2%80%8B%1B');
    expect(result.messages[0]).toContain('"??abc??"');
    for (const c of ['\u0000', '\u200b', '\u202e', '\u001b']) {
      expect(result.messages[0]).not.toContain(c);
    }
  });

  it('empty keys, bare keys and stray separators are ignored', () => {
    const result = decodeQuery(registry, '?&&=5&=&v=1&&seed=6&&');
    expect(result.params.seed).toBe(6);
    expect(result.messages).toEqual([]);
  });

  it('a value with an = inside is one value, not a second entry', () => {
    const result = decodeQuery(registry, '?v=1&seed=5=6');
    expect(result.params.seed).toBe(spec('seed').default);
    expect(result.messages[0]).toContain('"5=6" is not a number');
  });

  // Found by the fast-check property "decode(encode(decode(q))) keeps what was accepted":
  // `-0` for a param whose default is 0 came back as -0 (it equals 0 under ===).
  it('regression_minus_zero_is_read_as_zero', () => {
    const zeroDefault = registry.find((s) => s.default === 0);
    expect(zeroDefault).toBeDefined();
    if (!zeroDefault) return;
    const result = decodeQuery(registry, `?v=1&${zeroDefault.id}=-0`);
    expect(Object.is(result.params[zeroDefault.id], 0)).toBe(true);
    expect(result.messages).toEqual([]);
    expect(Object.is(decodeQuery(registry, '?v=1&seed=-0').params.seed, 0)).toBe(true);
  });
});
