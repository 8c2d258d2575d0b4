/**
 * Hostile edit lists through the real wasm API (a `Session`, as the worker keeps one): each gets
 * a structured error naming the edit and field, answers at once, and the last good tree stays.
 */
import { describe, expect, it } from 'vitest';
import { loadWasm } from '../testing/realWasm';

const brush = { radius: 0.6, density: 400, segment: 0.25, kill: 0.4 };
const paint = (points: unknown[], extra: object = {}) => ({
  op: 'paint',
  points,
  ...brush,
  ...extra,
});

/** [what, edit list, the field the error names, a part of its message]. */
const CASES: [string, unknown[], string, RegExp][] = [
  ['NaN coordinate', [paint([[1, 'NaN', 0]])], 'edits[0].points[0][1]', /must be a number/],
  ['null coordinate', [paint([[1, null, 0]])], 'edits[0].points[0][1]', /must be a number/],
  ['coordinate 1000 km away', [paint([[1e6, 5, 0]])], 'edits[0].points[0][0]', /-200 to 200/],
  ['radius 0', [paint([[1, 5, 0]], { radius: 0 })], 'edits[0].radius', /0\.02 to 10/],
  ['radius 1 km', [paint([[1, 5, 0]], { radius: 1000 })], 'edits[0].radius', /0\.02 to 10/],
  [
    'a stroke of 5,000 points',
    [paint(Array.from({ length: 5000 }, (_, i) => [i / 1000, 5, 0]))],
    'edits[0].points',
    /at most 4096/,
  ],
  [
    'a runaway stroke',
    [
      paint(
        Array.from({ length: 200 }, (_, i) => [i / 10 - 10, 5, 0]),
        { radius: 3, density: 5000 },
      ),
    ],
    'edits[0].density',
    /markers/,
  ],
  [
    'an outline that crosses itself',
    [
      {
        op: 'crown',
        outline: [
          [0, 2],
          [3, 8],
          [3, 2],
          [0, 9],
        ],
      },
    ],
    'edits[0].outline',
    /crosses itself/,
  ],
  ['a cut on the ground', [{ op: 'cut', at: [0.5, 0, 0.5] }], 'edits[0].at', /on the ground/],
  [
    'a bend across the tree',
    [{ op: 'bend', at: [0, 5, 0], to: [0, 5, 150] }],
    'edits[0].to',
    /across the tree/,
  ],
  [
    'thousands of edits',
    Array.from({ length: 3000 }, () => ({ op: 'cut', at: [1, 5, 0] })),
    'edits',
    /at most 1000/,
  ],
  ['an unknown op', [{ op: 'graft', at: [1, 5, 0] }], 'edits[0].op', /graft/],
];

describe('hostile edit lists through the wasm API', () => {
  const wasm = loadWasm();
  const session = new wasm.Session();
  session.update('{}', -1);
  const good = session.hash();

  it.each(CASES)('%s: an error naming the field; the tree is kept', (_, edits, param, message) => {
    let thrown: unknown = null;
    try {
      session.update(JSON.stringify({ edits }), -1);
    } catch (e) {
      thrown = e;
    }
    expect(typeof thrown).toBe('string');
    const error = JSON.parse(thrown as string) as { kind: string; param: string; message: string };
    expect(error.param).toBe(param);
    expect(error.message).toMatch(message);
    expect(['invalid_param', 'budget']).toContain(error.kind);
    expect(session.hash()).toBe(good);
  });

  it('a million brush points (11 MB of JSON) are refused by their size, before they are parsed', () => {
    const point = '[1.25,5.5,0.75]';
    const json = `{"edits":[{"op":"paint","radius":0.6,"density":400,"segment":0.25,"kill":0.4,"points":[${Array(1_000_000).fill(point).join(',')}]}]}`;
    let thrown: unknown = null;
    try {
      session.update(json, -1);
    } catch (e) {
      thrown = e;
    }
    const error = JSON.parse(thrown as string) as { param: string; message: string };
    expect(error.param).toBe('edits');
    expect(error.message).toMatch(/more than 4 MB/);
    expect(session.hash()).toBe(good);
  });
});
