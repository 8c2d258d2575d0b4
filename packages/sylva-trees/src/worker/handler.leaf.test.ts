/** Leaf inspector requests and tree foliage through the worker handler and the real wasm. */
import { describe, expect, it, vi } from 'vitest';
import { loadWasm } from '../testing/realWasm';
import { harness } from '../testing/workerHarness';
import { readyMessage } from './handler';
import type { LeafResponse, WorkerResponse } from './protocol';

const collect = () => harness();

function leafOf(sent: { message: WorkerResponse }[]): LeafResponse {
  const m = sent.at(-1)?.message;
  if (m?.type !== 'leaf') throw new Error(`expected a leaf, got ${JSON.stringify(m)}`);
  return m;
}

describe('leaf requests', () => {
  it('ready carries the leaf presets', () => {
    const names = (readyMessage(loadWasm()).leafPresets ?? []).map((p) => p.name);
    expect(names.length).toBeGreaterThan(2);
  });

  it('answers with the SVG and counts; the step replays growth', () => {
    const { sent, handle } = collect();
    handle({ type: 'leaf', id: 3, params: {}, step: -1, triangulation: false });
    const done = leafOf(sent);
    expect(done.id).toBe(3);
    expect(done.svg).toMatch(/^<\?xml[\s\S]*<svg[\s\S]*<\/svg>\s*$/);
    expect(done.iterations).toBeGreaterThan(2);
    expect(done.segments).toBe(done.nodes - 1 + done.links);
    handle({ type: 'leaf', id: 4, params: {}, step: 1, triangulation: true });
    const early = leafOf(sent);
    expect(early.segments).toBeLessThan(done.segments);
    expect(early.svg.length).not.toBe(done.svg.length);
    // The same leaf: the hash does not depend on the step.
    expect(early.hash).toBe(done.hash);
  });

  it('leaf params change the leaf; a bad value is a typed error', () => {
    const { sent, handle } = collect();
    handle({ type: 'leaf', id: 1, params: {}, step: -1, triangulation: false });
    const a = leafOf(sent);
    handle({ type: 'leaf', id: 2, params: { leaf_venation: 2 }, step: -1, triangulation: false });
    const b = leafOf(sent);
    expect(b.hash).not.toBe(a.hash);
    handle({ type: 'leaf', id: 5, params: { leaf_m: 99 }, step: -1, triangulation: false });
    const m = sent.at(-1)?.message;
    expect(m?.type).toBe('error');
    if (m?.type === 'error') {
      expect(m.id).toBe(5);
      expect(m.error.kind).toBe('invalid_param');
      expect(m.error.param).toBe('leaf_m');
    }
  });

  it('trees carry foliage; the texture is sent once per leaf shape', () => {
    const h = collect();
    const { sent, handle } = h;
    const params = { l1_branches: 6, l2_branches: 5 };
    handle({ type: 'generate', id: 1, params });
    const first = h.tree();
    const f = first.foliage;
    if (!f) throw new Error('no foliage');
    const leaves = first.meta.leaves ?? 0;
    expect(leaves).toBeGreaterThan(0);
    expect(f.matrices.length).toBe(leaves * 16);
    expect(f.colors.length).toBe(leaves * 3);
    expect(f.indices.length % 3).toBe(0);
    expect(f.positions.length / 3).toBe(f.uvs.length / 2);
    expect(f.texture?.rgba.length).toBe((f.texture?.width ?? 0) * (f.texture?.height ?? 0) * 4);
    expect(sent.find((s) => s.message.type === 'result')?.transfer).toContain(f.matrices.buffer);
    // Not even read out of the module when it is not sent (a 128 KiB copy per tree).
    const session = (loadWasm() as unknown as { Session: { prototype: object } }).Session;
    const read = vi.spyOn(session.prototype as { leaf_texture(): Uint8Array }, 'leaf_texture');
    handle({ type: 'generate', id: 2, params: { ...params, seed: 2 } });
    expect(h.lastResult().leafTexture).toBeUndefined();
    expect(h.tree().foliage?.texture).toBeNull();
    expect(read).not.toHaveBeenCalled();
    handle({ type: 'generate', id: 3, params: { ...params, leaf_lobes: 5 } });
    expect(h.tree().foliage?.texture).not.toBeNull();
    expect(read).toHaveBeenCalledTimes(1);
    read.mockRestore();
    handle({ type: 'generate', id: 4, params: { ...params, max_leaves: 0 } });
    const e = sent.at(-1)?.message;
    expect(e?.type === 'error' && e.error.kind).toBe('budget');
  });
});
