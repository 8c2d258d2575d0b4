/** Share-link encoding of the hand edit list (`e=`): round trips, the limit and hostile values. */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { editsProblem, type Edit, type EditPoint } from '../core/edits';
import { quantizeEdit } from '../core/editsQuantize';
import { decodeQuery } from './codec';
import {
  decodeEdits,
  editsFitLink,
  encodeEdits,
  EDITS_KEY,
  MAX_EDITS_LINK_LENGTH,
} from './editsCodec';

const coord = fc.double({ min: -199, max: 199, noNaN: true });
const height = fc.double({ min: 0.1, max: 199, noNaN: true });
const point = fc.tuple(coord, height, coord) as fc.Arbitrary<EditPoint>;

const edit: fc.Arbitrary<Edit> = fc.oneof(
  fc.record({
    op: fc.constant('paint' as const),
    points: fc.array(point, { minLength: 1, maxLength: 12 }),
    radius: fc.double({ min: 0.02, max: 10, noNaN: true }),
    density: fc.double({ min: 1, max: 5000, noNaN: true }),
    segment: fc.double({ min: 0.02, max: 2, noNaN: true }),
    kill: fc.double({ min: 2, max: 10, noNaN: true }),
  }),
  // A simple outline: a convex fan of angles around a centre.
  fc
    .tuple(fc.double({ min: 1, max: 5, noNaN: true }), fc.integer({ min: 3, max: 10 }))
    .map(([r, n]): Edit => ({
      op: 'crown',
      outline: Array.from({ length: n }, (_, k) => {
        const a = (2 * Math.PI * k) / n;
        return [6 + r * Math.cos(a), 8 + r * Math.sin(a)] as [number, number];
      }),
    })),
  fc.record({ op: fc.constant('cut' as const), at: point }),
  fc.record({ op: fc.constant('cut' as const), at: point, year: fc.integer({ min: 0, max: 300 }) }),
  fc.record({ op: fc.constant('bend' as const), at: point, to: point }),
);

/** Largest difference of any number of two edits of the same shape. */
function maxDiff(a: unknown, b: unknown): number {
  if (typeof a === 'number' && typeof b === 'number') return Math.abs(a - b);
  if (Array.isArray(a) && Array.isArray(b)) {
    return Math.max(0, ...a.map((x, i) => maxDiff(x, b[i])));
  }
  if (typeof a === 'object' && a && typeof b === 'object' && b) {
    const rb = b as Record<string, unknown>;
    return Math.max(0, ...Object.entries(a).map(([k, v]) => maxDiff(v, rb[k])));
  }
  return a === b ? 0 : Infinity;
}

describe('e= codec', () => {
  it('round-trips any edit list within the quantisation (0.5 cm, half a marker per m³)', () => {
    fc.assert(
      fc.property(fc.array(edit, { maxLength: 8 }), (list) => {
        const text = encodeEdits(list);
        const back = decodeEdits(text);
        expect(back.messages).toEqual([]);
        expect(back.edits.map((e) => e.op)).toEqual(list.map((e) => e.op));
        back.edits.forEach((e, i) => {
          const original = list[i] as Edit;
          const { density: d1 = 0, ...rest1 } = e as Edit & { density?: number };
          const { density: d2 = 0, ...rest2 } = original as Edit & { density?: number };
          expect(maxDiff(rest1, rest2)).toBeLessThanOrEqual(0.005 + 1e-9);
          expect(Math.abs(d1 - d2)).toBeLessThanOrEqual(0.5);
        });
        // Quantised edits (what the app keeps) round-trip exactly.
        const quantised = list.map(quantizeEdit);
        expect(decodeEdits(encodeEdits(quantised)).edits).toEqual(quantised);
      }),
      { numRuns: 300 },
    );
  });

  it('writes the compact form: cm integers, stroke points as differences, nothing to %-encode', () => {
    const edits: Edit[] = [
      {
        op: 'paint',
        points: [
          [1.2, 6, 0.3],
          [1.25, 6.1, 0.2],
        ],
        radius: 0.6,
        density: 400,
        segment: 0.25,
        kill: 0.4,
      },
      {
        op: 'crown',
        outline: [
          [0, 2],
          [2.5, 4],
          [2, 8],
          [0, 9],
        ],
      },
      { op: 'cut', at: [0.8, 4.1, -0.2] },
      { op: 'bend', at: [2, 5.5, 0], to: [2.3, 4.6, 0] },
      { op: 'cut', at: [0.5, 3, 0.1], year: 40 },
    ];
    const text = encodeEdits(edits);
    expect(text).toBe(
      '1~p60.400.25.40.120.600.30.5.10.-10~o0.200.250.200.-50.400.-200.100~c80.410.-20~b200.550.0.230.460.0~c50.300.10.40',
    );
    expect(encodeURIComponent(text)).toBe(text);
    expect(decodeEdits(text)).toEqual({ edits, messages: [] });
    expect(encodeEdits([])).toBe('');
  });

  it('fits a 40-point stroke and tells when a history is too long for the link', () => {
    const stroke: Edit = {
      op: 'paint',
      points: Array.from({ length: 40 }, (_, k) => [2 + k * 0.05, 6 + k * 0.03, 0.5]),
      radius: 0.6,
      density: 400,
      segment: 0.25,
      kill: 0.4,
    };
    expect(editsFitLink([stroke])).toBe(true);
    const many = Array.from({ length: 40 }, () => stroke);
    expect(encodeEdits(many).length).toBeGreaterThan(MAX_EDITS_LINK_LENGTH);
    expect(editsFitLink(many)).toBe(false);
  });

  it.each([
    ['2~c80.410.-20', /unsupported version "2"/],
    ['1~c80.410', /e\[0\]: a cut takes 3 numbers \(and a year\), got 2/],
    ['1~c80.410.0.40.1', /e\[0\]: a cut takes 3 numbers \(and a year\), got 5/],
    ['1~c80.410.0.301', /edits\[0\]\.year is 301: allowed range is 0 to 300 years/],
    ['1~c80.410.0.-1', /edits\[0\]\.year is -1: allowed range is 0 to 300 years/],
    ['1~cNaN.410.0', /e\[0\]: "NaN" is not a whole number/],
    ['1~c1e5.410.0', /"1e5" is not a whole number/],
    ['1~c0x10.410.0', /"0x10" is not a whole number/],
    ['1~c99999999.410.0', /"99999999" is not a whole number/],
    ['1~c80.410.-20~q1.2.3', /e\[1\]: unknown op "q"/],
    ['1~c50000.410.0', /edits\[0\]\.at\[0\] is 500: allowed range is -200 to 200 m/],
    ['1~c80.0.0', /edits\[0\]\.at is on the ground/],
    ['1~p0.400.25.40.0.100.0', /edits\[0\]\.radius is 0: allowed range is 0.02 to 10 m/],
    ['1~p60.400.25.40.0.100', /a paint stroke takes 4 numbers and x,y,z per point/],
    ['1~o0.0.200.200.0.-200.-200.200', /edits\[0\]\.outline crosses itself/],
    ['1~<script>', /e\[0\]: "script>" is not a whole number/],
    ['garbage', /unsupported version "garbage"/],
    ['too long', /too long \(\d+ characters, limit 2000\)/],
  ])('drops every edit of %s with a message', (label, message) => {
    const value = label === 'too long' ? `1~${'c1.100.1~'.repeat(300)}` : label;
    const result = decodeEdits(value);
    expect(result.edits).toEqual([]);
    expect(result.messages).toHaveLength(1);
    expect(result.messages[0]).toMatch(message);
    expect(result.messages[0]).toMatch(/^Ignored the edits in the link: .*Import edits…/);
  });

  it('only yields edits the validator accepts, whatever the input', () => {
    const text = fc.oneof(
      fc.string({ maxLength: 80 }),
      fc
        .array(
          fc.oneof(fc.constantFrom('p', 'o', 'c', 'b', '.', '~', '-'), fc.nat(99999).map(String)),
          { maxLength: 40 },
        )
        .map((a) => `1~${a.join('')}`),
    );
    fc.assert(
      fc.property(text, (value) => {
        const result = decodeEdits(value);
        expect(editsProblem(result.edits)).toBeNull();
        if (result.edits.length === 0) return;
        expect(result.messages).toEqual([]);
      }),
      { numRuns: 500 },
    );
  });

  it('the page query limit does not count e= (it has its own)', () => {
    const value = '1~' + Array.from({ length: 100 }, () => 'c1000.10000.-1000').join('~');
    expect(value.length).toBeLessThanOrEqual(MAX_EDITS_LINK_LENGTH);
    const registry = [] as Parameters<typeof decodeQuery>[0];
    const long = `v=1&${EDITS_KEY}=${value}&x=${'1'.repeat(3000)}`;
    expect(decodeQuery(registry, long).messages).toEqual([]);
  });
});
