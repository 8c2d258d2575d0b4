/** The worker side of wind and bark: defensive reads, one bark bake per worker, transfers. */
import { describe, expect, it } from 'vitest';
import type { WasmApi } from '../core/types';
import { loadWasm } from '../testing/realWasm';
import { harness } from '../testing/workerHarness';
import { barkOf, windOf } from '../worker/generate';
import { buildTreeGeometry } from './geometry';
import { mergeUpdate } from './treeState';

describe('wind data from the core', () => {
  it('is used only when it matches the vertex count', () => {
    const good = new Float32Array(16);
    expect(windOf(good, 2)).toBe(good);
    expect(windOf(new Float32Array(15), 2)).toHaveLength(0);
    expect(windOf(new Float32Array(0), 2)).toHaveLength(0);
    expect(windOf(new Float32Array(0), 0)).toHaveLength(0);
  });

  it('bark maps need both getters', () => {
    const wasm = loadWasm();
    const partial = { ...wasm, bark_style_json: undefined } as WasmApi;
    expect(barkOf(partial)).toBeUndefined();
  });

  it('bark maps go out again when the bark type changes; the shade with every new bark', () => {
    const h = harness();
    for (const [id, bark_type] of [
      [1, 0],
      [2, 0],
      [3, 3],
      [4, 3],
    ] as const) {
      h.handle({ type: 'generate', id, params: { bark_type, leaves: 2 } });
    }
    const results = h.sent.filter((s) => s.message.type === 'result');
    const r = h.results();
    expect(r.map((x) => x.barkTextures?.kind)).toEqual([0, undefined, 3, undefined]);
    expect(r[2]?.barkTextures?.color).not.toEqual(r[0]?.barkTextures?.color);
    expect(results[2]?.transfer).toContain(r[2]?.barkTextures?.orm.buffer);
    // A new bark brings its occlusion (one byte per vertex); an unchanged tree sends neither.
    expect(r.map((x) => x.shade !== undefined)).toEqual([true, false, true, false]);
    for (const [i, x] of r.entries()) {
      if (!x.shade) continue;
      expect(x.shade).toHaveLength(x.meta.vertices);
      expect(results[i]?.transfer).toContain(x.shade.buffer);
    }
    expect(h.tree().shade).toHaveLength(h.tree().meta.vertices);
  });

  it('the first result carries the bark maps and the wind buffer, transferred', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: { seed: 2 } });
    h.handle({ type: 'generate', id: 2, params: { seed: 3 } });
    const results = h.sent.filter((s) => s.message.type === 'result');
    expect(results).toHaveLength(2);
    const [first, second] = h.results();
    if (!first || !second) throw new Error('no results');
    expect(first.barkTextures?.size).toBe(256);
    expect(first.barkTextures?.color).toHaveLength(256 * 256 * 4);
    expect(results[0]?.transfer).toEqual(
      expect.arrayContaining([first.barkTextures?.color.buffer, first.barkTextures?.normal.buffer]),
    );
    expect(second.barkTextures).toBeUndefined();
    // Wind: the core's 8 floats per vertex, transferred.
    let tree = null;
    for (const [i, r] of [first, second].entries()) {
      const wind = r.bark?.wind ?? new Float32Array(0);
      expect(wind.length).toBe(((r.bark?.positions.length ?? 0) / 3) * 8);
      expect(wind.length).toBeGreaterThan(0);
      expect(results[i]?.transfer).toContain(wind.buffer);
      tree = mergeUpdate(tree, r);
      const geometry = buildTreeGeometry(tree);
      expect(geometry.hasAttribute('windPivot')).toBe(true);
    }
  });
});
