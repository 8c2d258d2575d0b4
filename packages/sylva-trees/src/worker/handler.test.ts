/** Worker handler tests through the real wasm in Node: generation, typed errors, panic recovery. */
import { describe, expect, it } from 'vitest';
import { defaultParams } from '../core/params';
import { buildTreeGeometry } from '../viewer/geometry';
import { loadDebugWasm, loadWasm, realRegistry } from '../testing/realWasm';
import { harness } from '../testing/workerHarness';
import { debugHooks, type DebugResponse } from './debug';
import { createHandler, readyMessage } from './handler';
import type { WorkerResponse } from './protocol';
import type { Params } from '../core/types';

/** One request answered with a result and then its hash; the merged tree. */
function onlyTree(h: ReturnType<typeof harness>) {
  expect(h.sent.map((s) => s.message.type)).toEqual(['result', 'hash']);
  return h.tree();
}

describe('real wasm through the worker handler', () => {
  it('ready carries the registry, presets and version', () => {
    const ready = readyMessage(loadWasm());
    expect(ready.registry.length).toBeGreaterThan(3);
    expect(ready.registry.map((s) => s.id)).toEqual(
      expect.arrayContaining(['seed', 'scale', 'l1_length']),
    );
    expect(ready.presets.length).toBeGreaterThan(0);
    expect(ready.version).toMatch(/\d+\.\d+/);
    const groups = ready.registry.map((s) => s.group);
    expect(new Set(groups).size).toBeGreaterThan(1);
  });

  it('generates the default tree with buffer lengths that agree with meta', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: {} });
    const result = onlyTree(h);
    const { sent } = h;
    const { meta } = result;
    expect(h.lastResult().id).toBe(1);
    expect(h.lastResult().meta.hash).toBe('');
    expect(sent[1]?.message).toEqual({ type: 'hash', id: 1, hash: meta.hash });
    expect(meta.vertices).toBeGreaterThan(100);
    expect(result.positions.length).toBe(meta.vertices * 3);
    expect(result.normals.length).toBe(meta.vertices * 3);
    expect(result.uvs.length).toBe(meta.vertices * 2);
    expect(result.indices.length).toBe(meta.triangles * 3);
    // The crown envelope preview: whole line segments of 3D points around the tree.
    expect(result.envelope.length).toBeGreaterThan(0);
    expect(result.envelope.length % 6).toBe(0);
    expect(meta.hash).toMatch(/^[0-9a-f]{16}$/);
    const covered = meta.groups.reduce((sum, g) => sum + g.count, 0);
    expect(covered).toBe(result.indices.length);
    let maxIndex = 0;
    for (const i of result.indices) if (i > maxIndex) maxIndex = i;
    expect(maxIndex).toBeLessThan(meta.vertices);
    expect(meta.bounds.min[1]).toBeGreaterThanOrEqual(-1e-3);
    expect(meta.bounds.max[1]).toBeGreaterThan(meta.bounds.min[1]);
    // Every buffer is transferred (the tree's five plus the growth markers, empty here).
    const buffers = [result.positions, result.normals, result.uvs, result.indices, result.envelope];
    expect(sent[0]?.transfer).toEqual(
      expect.arrayContaining([...buffers.map((b) => b.buffer), result.markers?.buffer]),
    );
  });

  it('explicit defaults give the same hash as an empty object (deterministic)', () => {
    const a = harness();
    a.handle({ type: 'generate', id: 1, params: {} });
    const b = harness();
    b.handle({ type: 'generate', id: 2, params: defaultParams(realRegistry()) });
    expect(onlyTree(b).meta.hash).toBe(onlyTree(a).meta.hash);
  });

  it('builds a three.js geometry from the buffers without copying', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: { seed: 3 } });
    const result = onlyTree(h);
    const geometry = buildTreeGeometry(result);
    expect(geometry.getAttribute('position').array).toBe(result.positions);
    expect(geometry.getIndex()?.array).toBe(result.indices);
    expect(geometry.groups.length).toBe(result.meta.groups.length);
    expect(geometry.boundingSphere?.radius).toBeGreaterThan(0);
    geometry.dispose();
  });

  it('an invalid value gives a typed error naming the param', () => {
    const { sent, handle } = harness();
    handle({ type: 'generate', id: 7, params: { scale: -5 } });
    const message = sent[0]?.message;
    expect(message?.type).toBe('error');
    if (message?.type !== 'error') return;
    expect(message.id).toBe(7);
    expect(message.error.kind).toBe('invalid_param');
    expect(message.error.param).toBe('scale');
    expect(message.error.message).toContain('scale');
  });

  it('an unknown param gives an unknown_param error', () => {
    const { sent, handle } = harness();
    handle({ type: 'generate', id: 8, params: { no_such_param: 1 } as Params });
    const message = sent[0]?.message;
    expect(message?.type === 'error' && message.error.kind).toBe('unknown_param');
  });

  // Found by the proptest property "valid values are accepted and pass validation": a float
  // bound that f32 cannot hold (ratio 0.2, prune_width 0.01) was accepted, then refused as
  // "ratio is 0.20000000298023224: allowed range is 0.001 to 0.2" when the tree was generated.
  it('regression_f32_rounded_bounds_generate', () => {
    const bounds = realRegistry()
      .filter((s) => s.kind === 'float')
      .flatMap((s) => [s.min, s.max].map((v) => [s.id, v] as const))
      .filter(([, v]) => Math.fround(v) !== v);
    expect(bounds.map(([id]) => id)).toEqual(expect.arrayContaining(['ratio', 'prune_width']));
    for (const [id, value] of bounds) {
      const { sent, handle } = harness();
      // leaves: 0: the range check is what is tested; a leaf shape at a bound may be refused
      // by the leaf's own rules (e.g. a blade of almost no area) once foliage builds it.
      handle({ type: 'generate', id: 1, params: { levels: 1, leaves: 0, [id]: value } });
      expect(sent[0]?.message.type, `${id}=${value}`).toBe('result');
    }
  });

  it('the shipped core has no test hook', () => {
    expect('debug_panic' in loadWasm()).toBe(false);
  });

  it('debug-panic makes the debug core panic: reported as fatal, then further work refused', async () => {
    const sent: { message: WorkerResponse | DebugResponse }[] = [];
    const handle = createHandler(await loadDebugWasm(), (message) => sent.push({ message }), {
      debug: debugHooks,
    });
    handle({ type: 'debug-panic' });
    const fatal = sent[0]?.message;
    expect(fatal?.type).toBe('fatal');
    if (fatal?.type !== 'fatal') return;
    expect(fatal.message).toMatch(/panic/i);
    handle({ type: 'generate', id: 9, params: {} });
    expect(sent[1]?.message.type).toBe('fatal');
  });
});
