/**
 * The hand edit list's validator and JSON reader: good lists pass, and every hostile case is
 * rejected with the core's message naming `edits[i].field` (core-rs/sylva-core/src/params/edits).
 */
import { describe, expect, it } from 'vitest';
import {
  EditsError,
  editsProblem,
  firstCrossing,
  formatF32,
  MAX_EDITS,
  MAX_STROKE_POINTS,
  validateEdits,
  type Edit,
} from './edits';
import { coreInput, editsDocument, parseEditsDocument, parseEditsValue } from './editsJson';
import { quantizeEdit } from './editsQuantize';

const ISSUE_EXAMPLE = `{"version": 1, "edits": [
  {"op": "paint", "points": [[1.2, 6.0, 0.3], [1.9, 6.4, 0.2]], "radius": 0.6, "density": 400, "segment": 0.25, "kill": 0.4},
  {"op": "crown", "outline": [[0, 2], [2.5, 4], [2, 8], [0, 9]]},
  {"op": "cut", "at": [0.8, 4.1, -0.2]},
  {"op": "bend", "at": [2.0, 5.5, 0.0], "to": [2.3, 4.6, 0.0]}
]}`;

const paint = (over: Partial<Extract<Edit, { op: 'paint' }>> = {}): Edit => ({
  op: 'paint',
  points: [[1, 5, 0]],
  radius: 0.6,
  density: 400,
  segment: 0.25,
  kill: 0.4,
  ...over,
});

/** The error `fn` throws (an EditsError), for its field and message. */
function failure(fn: () => unknown): { param: string; message: string } {
  try {
    fn();
  } catch (error) {
    if (error instanceof EditsError) return { param: error.param, message: error.message };
    throw error;
  }
  throw new Error('expected an EditsError');
}

describe('edit list JSON', () => {
  it("reads the issue's example document and writes it back", () => {
    const edits = parseEditsDocument(ISSUE_EXAMPLE);
    expect(edits.map((e) => e.op)).toEqual(['paint', 'crown', 'cut', 'bend']);
    expect(edits[2]).toEqual({ op: 'cut', at: [0.8, 4.1, -0.2] });
    expect(parseEditsDocument(editsDocument(edits))).toEqual(edits);
    // A bare array is accepted too.
    expect(
      parseEditsDocument(JSON.stringify((JSON.parse(ISSUE_EXAMPLE) as { edits: unknown }).edits)),
    ).toEqual(edits);
  });

  it.each([
    ['not json', 'edits', /must be JSON like/],
    ['{"version": 2, "edits": []}', 'version', /^version must be 1, got 2$/],
    ['{"version": 1, "edits": [], "x": 1}', 'x', /^'x' is not a field of the edit list/],
    ['{"version": 1, "edits": {}}', 'edits', /^edits must be an array of edits$/],
    ['[1]', 'edits[0]', /^edits\[0\] must be an object$/],
    ['[{"op": "grow"}]', 'edits[0].op', /^edits\[0\]\.op is 'grow': it must be "paint"/],
    ['[{"at": [1, 2, 3]}]', 'edits[0].op', /is '': it must be/],
    [
      '[{"op": "cut", "at": [1, 2, 3], "to": [0, 1, 0]}]',
      'edits[0].to',
      /not a field of a cut edit \(op, at, year\)/,
    ],
    [
      '[{"op": "cut", "at": [1, 2, 3], "year": "May"}]',
      'edits[0].year',
      /must be a number, got "May"/,
    ],
    [
      '[{"op": "cut", "at": [1, 2, 3], "year": 1e9}]',
      'edits[0].year',
      /is 1000000000: allowed range is 0 to 300 years/,
    ],
    ['[{"op": "cut"}]', 'edits[0].at', /^edits\[0\]\.at is missing$/],
    ['[{"op": "cut", "at": [1, 2]}]', 'edits[0].at', /must be an array of 3 numbers, got \[1,2\]/],
    ['[{"op": "cut", "at": [1, "2", 3]}]', 'edits[0].at[1]', /must be a number, got "2"/],
    [
      '[{"op": "crown", "outline": [[0, 1], [1, 2]]}]',
      'edits[0].outline',
      /has 2 points: at least 3/,
    ],
    ['[{"op": "paint", "points": 5}]', 'edits[0].points', /must be an array of points/],
  ])('rejects %s naming %s', (text, param, message) => {
    const error = failure(() => parseEditsDocument(text));
    expect(error.param).toBe(param);
    expect(error.message).toMatch(message);
  });

  it('rejects too many edits and strokes of too many points before reading them', () => {
    const many = Array.from({ length: MAX_EDITS + 1 }, () => ({ op: 'cut', at: [0, 1, 0] }));
    expect(failure(() => parseEditsValue(many)).message).toBe(
      'edits has 1001 edits: at most 1000 are allowed',
    );
    const points = Array.from({ length: MAX_STROKE_POINTS + 1 }, () => [0, 1, 0]);
    const stroke = { ...paint(), points };
    expect(failure(() => parseEditsValue([stroke]))).toEqual({
      param: 'edits[0].points',
      message: 'edits[0].points has 4097 points: at most 4096 are allowed',
    });
  });

  it('sends "edits" to the core only when there are some', () => {
    expect(coreInput({ seed: 1 }, undefined, [])).toEqual({ seed: 1 });
    const input = coreInput({ seed: 1 }, [], [{ op: 'cut', at: [1, 2, 3] }]);
    expect(input).toEqual({ seed: 1, edits: [{ op: 'cut', at: [1, 2, 3] }] });
  });
});

describe('validateEdits', () => {
  it('accepts good edits', () => {
    expect(() => validateEdits(parseEditsDocument(ISSUE_EXAMPLE))).not.toThrow();
    expect(editsProblem([])).toBeNull();
  });

  it.each<[string, Edit, string, string]>([
    [
      'a radius of 0',
      paint({ radius: 0 }),
      'edits[0].radius',
      'edits[0].radius is 0: allowed range is 0.02 to 10 m',
    ],
    [
      'a radius of 1 km',
      paint({ radius: 1000 }),
      'edits[0].radius',
      'edits[0].radius is 1000: allowed range is 0.02 to 10 m',
    ],
    [
      'a NaN density',
      paint({ density: NaN }),
      'edits[0].density',
      'edits[0].density is NaN: allowed range is 1 to 5000 markers per m³',
    ],
    [
      'an infinite segment',
      paint({ segment: Infinity }),
      'edits[0].segment',
      'edits[0].segment is inf: allowed range is 0.02 to 2 m',
    ],
    [
      'a kill under the segment',
      paint({ segment: 0.5, kill: 0.3 }),
      'edits[0].kill',
      'edits[0].kill is 0.3: it must be at least the segment length 0.5 m (else new shoots step past their markers)',
    ],
    [
      'a NaN point',
      paint({ points: [[1, NaN, 0]] }),
      'edits[0].points[0][1]',
      'edits[0].points[0][1] is NaN: allowed range is -200 to 200 m',
    ],
    [
      'a point 1 km away',
      paint({
        points: [
          [0, 1, 0],
          [1000, 1, 0],
        ],
      }),
      'edits[0].points[1][0]',
      'edits[0].points[1][0] is 1000: allowed range is -200 to 200 m',
    ],
    [
      'a cut on the ground',
      { op: 'cut', at: [1, 0, 0] },
      'edits[0].at',
      'edits[0].at is on the ground (y = 0 m): a cut or bend names a branch above 0.05 m',
    ],
    [
      'a bend to far away',
      { op: 'bend', at: [1, 2, 0], to: [1, 2, -500] },
      'edits[0].to[2]',
      'edits[0].to[2] is -500: allowed range is -200 to 200 m',
    ],
    [
      'a negative outline radius',
      {
        op: 'crown',
        outline: [
          [-1, 2],
          [2, 4],
          [0, 9],
        ],
      },
      'edits[0].outline[0][0]',
      'edits[0].outline[0][0] is -1: allowed range is 0 to 200 m',
    ],
    [
      'an outline crossing itself',
      {
        op: 'crown',
        outline: [
          [0, 0],
          [2, 2],
          [2, 0],
          [0, 2],
        ],
      },
      'edits[0].outline',
      'edits[0].outline crosses itself (its edges 0 and 2 intersect): draw a simple closed outline',
    ],
  ])('rejects %s', (_name, edit, param, message) => {
    const error = failure(() =>
      validateEdits([{ op: 'cut', at: [0, 1, 0] } as Edit, edit].slice(1)),
    );
    expect(error).toEqual({ param, message });
    // The index in the message is the edit's place in the list.
    const later = failure(() => validateEdits([{ op: 'cut', at: [0, 1, 0] }, edit]));
    expect(later.param).toBe(param.replace('edits[0]', 'edits[1]'));
  });

  it('rejects more than 65,536 points in all, naming the edit where the count passes it', () => {
    const stroke = paint({ points: Array.from({ length: 4096 }, () => [0, 1, 0]) });
    const edits = Array.from({ length: 17 }, () => stroke);
    expect(failure(() => validateEdits(edits))).toEqual({
      param: 'edits',
      message:
        'the edits hold more than 65536 points in all (at edits[16]): split the work into fewer, shorter strokes',
    });
  });

  it('finds self-crossings like the core and passes simple outlines', () => {
    expect(
      firstCrossing([
        [0, 2],
        [2.5, 4],
        [2, 8],
        [0, 9],
      ]),
    ).toBeNull();
    // Adjacent edges folding back onto each other.
    expect(
      firstCrossing([
        [0, 0],
        [2, 0],
        [1, 0],
      ]),
    ).not.toBeNull();
  });

  it('prints numbers as the core prints an f32', () => {
    expect(formatF32(0.1 + 0.2)).toBe('0.3');
    expect(formatF32(1e30)).toBe('1000000000000000000000000000000');
    expect(formatF32(-Infinity)).toBe('-inf');
  });
});

describe('quantizeEdit', () => {
  it('rounds to centimetres and keeps a cut off the ground and the kill at least the segment', () => {
    expect(quantizeEdit({ op: 'cut', at: [0.123, 0.054, -0.005] })).toEqual({
      op: 'cut',
      at: [0.12, 0.06, 0],
    });
    const q = quantizeEdit(paint({ radius: 0.604, density: 399.6, segment: 0.253, kill: 0.2 }));
    expect(q).toMatchObject({ radius: 0.6, density: 400, segment: 0.25, kill: 0.25 });
    expect(editsProblem([q])).toBeNull();
  });
});
