/**
 * The core's `simd128` lanes in wasm against the scalar rule they stand for, through the debug
 * core's hooks (`debug-hooks` feature): natively these functions take the scalar path, so only
 * the wasm module runs the lanes.
 */
import { describe, expect, it } from 'vitest';
import { mulberry32 } from '../core/random';
import { loadDebugWasm, loadWasm } from './realWasm';

type NearX = (positions: Float32Array, lo: number, hi: number) => Uint32Array;

/** `[n, v...]` by the rule `near_x` documents: groups of four, left out only when each vertex is. */
function expected(positions: Float32Array, lo: number, hi: number): number[] {
  const n = Math.floor(positions.length / 12) * 4;
  const outside = (v: number) => positions[3 * v]! < lo || positions[3 * v]! > hi;
  const seen: number[] = [];
  for (let g = 0; g < n; g += 4) {
    if (![0, 1, 2, 3].every((k) => outside(g + k))) seen.push(g, g + 1, g + 2, g + 3);
  }
  return [n, ...seen];
}

describe('holes: the scan for vertices near the holes (near_x)', () => {
  it('is not in the shipped core', () => {
    expect('debug_near_x' in loadWasm()).toBe(false);
  });

  it('hands on every group of four with a vertex not certainly outside, and only those', async () => {
    const nearX = (await loadDebugWasm()) as unknown as { debug_near_x: NearX };
    const f = Math.fround;
    const [lo, hi] = [f(-0.75), f(1.25)];
    const edge = [lo, hi, f(lo - 1e-6), f(hi + 1e-6), -0, 0, NaN, Infinity, -Infinity, f(0.1)];
    const random = mulberry32(7);
    for (const vertices of [0, 3, 4, 5, 8, 64, 1001, 4099]) {
      const p = new Float32Array(3 * vertices);
      for (let v = 0; v < vertices; v++) {
        // Mostly far outside, some near the range, the edge values now and then.
        const r = random();
        p[3 * v] =
          r < 0.1 ? edge[v % edge.length]! : r < 0.2 ? random() * 2 - 0.75 : random() * 100 + 2;
        p[3 * v + 1] = random();
        p[3 * v + 2] = NaN;
      }
      const got = [...nearX.debug_near_x(p, lo, hi)];
      expect(got, `${vertices} vertices`).toEqual(expected(p, lo, hi));
      // Nothing inside the range is left out of the groups scanned.
      const n = got[0]!;
      for (let v = 0; v < n; v++) {
        if (!(p[3 * v]! < lo || p[3 * v]! > hi)) expect(got.slice(1)).toContain(v);
      }
    }
  });
});
