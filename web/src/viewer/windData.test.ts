/** The worker side of wind and bark: defensive reads, one bark bake per worker, transfers. */
import { describe, expect, it } from 'vitest';
import type { WasmApi, WasmTree } from '../core/types';
import { loadWasm } from '../testing/realWasm';
import { barkOf, createHandler, windOf } from '../worker/handler';
import type { ResultResponse, WorkerResponse } from '../worker/protocol';
import { buildTreeGeometry } from './geometry';

const fakeTree = (extra: Partial<WasmTree> = {}): WasmTree =>
  ({ positions: () => new Float32Array(6), ...extra }) as WasmTree;

describe('wind data from the core', () => {
  it('is read only when the getter exists and matches the vertex count', () => {
    expect(windOf(fakeTree(), 2)).toHaveLength(0);
    const good = new Float32Array(16);
    expect(windOf(fakeTree({ wind: () => good }), 2)).toBe(good);
    expect(windOf(fakeTree({ wind: () => new Float32Array(15) }), 2)).toHaveLength(0);
    expect(windOf(fakeTree({ wind: () => new Float32Array(0) }), 2)).toHaveLength(0);
  });

  it('bark maps need both getters', () => {
    const wasm = loadWasm();
    const partial = { ...wasm, bark_style_json: undefined } as WasmApi;
    expect(barkOf(partial)).toBeUndefined();
  });

  it('bark maps go out again when the bark type changes, with the shade each time', () => {
    const sent: { message: WorkerResponse; transfer: Transferable[] }[] = [];
    const handle = createHandler(loadWasm(), (message, transfer) =>
      sent.push({ message, transfer }),
    );
    for (const [id, bark_type] of [
      [1, 0],
      [2, 0],
      [3, 3],
      [4, 3],
    ] as const) {
      handle({ type: 'generate', id, params: { bark_type, leaves: 2 } });
    }
    const results = sent.filter((s) => s.message.type === 'result');
    const r = results.map((x) => x.message as ResultResponse);
    expect(r.map((x) => x.bark?.kind)).toEqual([0, undefined, 3, undefined]);
    expect(r[2]?.bark?.color).not.toEqual(r[0]?.bark?.color);
    expect(results[2]?.transfer).toContain(r[2]?.bark?.orm.buffer);
    for (const [i, x] of r.entries()) {
      expect(x.shade).toHaveLength(x.positions.length / 3);
      expect(results[i]?.transfer).toContain(x.shade?.buffer);
    }
  });

  it('the first result carries the bark maps and the wind buffer, transferred', () => {
    const sent: { message: WorkerResponse; transfer: Transferable[] }[] = [];
    const handle = createHandler(loadWasm(), (message, transfer) =>
      sent.push({ message, transfer }),
    );
    handle({ type: 'generate', id: 1, params: { seed: 2 } });
    handle({ type: 'generate', id: 2, params: { seed: 3 } });
    const results = sent.filter((s) => s.message.type === 'result');
    expect(results).toHaveLength(2);
    const [first, second] = results.map((r) => r.message as ResultResponse);
    if (!first || !second) throw new Error('no results');
    expect(first.bark?.size).toBe(256);
    expect(first.bark?.color).toHaveLength(256 * 256 * 4);
    expect(results[0]?.transfer).toEqual(
      expect.arrayContaining([first.bark?.color.buffer, first.bark?.normal.buffer]),
    );
    expect(second.bark).toBeUndefined();
    // Wind: either the core's 8 floats per vertex or empty (older core), always transferred.
    for (const [i, r] of [first, second].entries()) {
      const wind = r.wind ?? new Float32Array(0);
      expect([0, (r.positions.length / 3) * 8]).toContain(wind.length);
      expect(results[i]?.transfer).toContain(wind.buffer);
      const geometry = buildTreeGeometry(r);
      expect(geometry.hasAttribute('windPivot')).toBe(wind.length > 0);
    }
  });
});
