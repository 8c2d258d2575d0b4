/**
 * Incremental generation through the worker handler and the real wasm: only changed arrays
 * travel, viewer edits cost nothing, previews during a drag, the hash after the buffers.
 */
import { describe, expect, it } from 'vitest';
import { loadWasm } from '../testing/realWasm';
import { harness } from '../testing/workerHarness';
import { mergeUpdate } from '../viewer/treeState';
import type { TreeBuffers } from '../core/types';
import { createHandler } from './handler';
import type { ResultResponse, WorkerResponse } from './protocol';

const BASE = { l1_branches: 12, l2_branches: 8 };

/** The hash of a cold generation of `params` in a fresh handler. */
function coldHash(params: Record<string, number>): string {
  const h = harness();
  h.handle({ type: 'generate', id: 1, params });
  return h.tree().meta.hash;
}

/** Which arrays a result carries. */
function parts(r: ResultResponse): string[] {
  const keys = ['bark', 'envelope', 'markers', 'instances', 'leafMesh', 'leafTexture', 'shade'];
  return (keys as (keyof ResultResponse)[]).filter((k) => r[k] !== undefined);
}

describe('session generation in the worker', () => {
  it('sends only what changed, and the merged tree hashes like a cold one', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: BASE });
    expect(parts(h.lastResult())).toEqual([
      'bark',
      'envelope',
      'markers',
      'instances',
      'leafMesh',
      'leafTexture',
      'shade',
    ]);
    const edits: [Record<string, number>, string[]][] = [
      // New leaves shade the bark differently: its occlusion comes along.
      [{ foliage_angle: 20 }, ['instances', 'shade']],
      [{ foliage_angle: 20, leaf_margin: 1, leaf_teeth: 30 }, ['leafMesh', 'leafTexture']],
      [{ foliage_angle: 20, leaf_margin: 1, leaf_teeth: 30, lobes: 3 }, ['bark', 'shade']],
      [
        { foliage_angle: 20, leaf_margin: 1, leaf_teeth: 30, lobes: 3, seed: 4 },
        ['bark', 'envelope', 'markers', 'instances', 'shade'],
      ],
    ];
    let id = 2;
    for (const [edit, expected] of edits) {
      const params = { ...BASE, ...edit };
      h.handle({ type: 'generate', id, params });
      const result = h.lastResult();
      expect(result.id).toBe(id);
      expect(parts(result), JSON.stringify(edit)).toEqual(expected);
      // Transferred: exactly the buffers it carries.
      const sent = h.sent.find((s) => s.message === result);
      // The bark: positions, normals, uvs, indices, wind and its pick boxes.
      const buffers: Partial<Record<string, number>> = { bark: 6, instances: 2, leafMesh: 4 };
      expect(sent?.transfer.length).toBe(parts(result).reduce((n, k) => n + (buffers[k] ?? 1), 0));
      expect(h.tree().meta.hash, JSON.stringify(edit)).toBe(coldHash(params));
      id++;
    }
  });

  it('a viewer-only edit regenerates nothing and sends no arrays', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: BASE });
    const hash = h.tree().meta.hash;
    h.handle({ type: 'generate', id: 2, params: { ...BASE, show_preview: 1 } });
    const r = h.lastResult();
    expect(parts(r)).toEqual([]);
    expect(r.meta.changes).toEqual({
      skeleton: false,
      bark: false,
      placements: false,
      leaf_mesh: false,
      leaf: false,
      shade: false,
    });
    expect(h.tree().meta.hash).toBe(hash);
  });

  it('a drag gets a preview without a hash; the settle brings the full tree and its hash', () => {
    const sent: WorkerResponse[] = [];
    // Budget 0: every bark is over it, so a drag is always answered with a preview.
    const handle = createHandler(loadWasm(), (m) => sent.push(m), {
      defer: (task) => {
        task();
        return () => undefined;
      },
      previewBudgetMs: 0,
    });
    handle({ type: 'generate', id: 1, params: BASE });
    handle({ type: 'generate', id: 2, params: { ...BASE, l1_length: 0.35 }, preview: true });
    const preview = sent.at(-1);
    if (preview?.type !== 'result') throw new Error(JSON.stringify(preview));
    expect(preview.meta.preview).toBe(true);
    expect(preview.bark).toBeDefined();
    handle({ type: 'generate', id: 3, params: { ...BASE, l1_length: 0.35 } });
    const full = sent.at(-2);
    if (full?.type !== 'result') throw new Error(JSON.stringify(full));
    expect(full.meta.preview).toBe(false);
    // The bark is swept again (with its occlusion, which a preview goes without) and every
    // leaf is placed (the preview placed every other site, lit by the previous crown): the
    // skeleton and the leaf were full.
    expect(parts(full)).toEqual(['bark', 'instances', 'shade']);
    if (!preview.instances || !full.instances) throw new Error('no leaves sent');
    const leaves = (m: Float32Array) => m.length / 16;
    expect(leaves(preview.instances.matrices)).toBe(Math.ceil(leaves(full.instances.matrices) / 2));
    // The preview's first leaf is the full tree's first leaf, √2 larger.
    const size = (m: Float32Array) => Math.hypot(m[4]!, m[5]!, m[6]!);
    expect(size(preview.instances.matrices) / size(full.instances.matrices)).toBeCloseTo(
      Math.SQRT2,
      4,
    );
    expect(preview.shade).toHaveLength(0);
    expect(full.meta.vertices).toBeGreaterThan(preview.meta.vertices);
    const hashes = sent.filter((m) => m.type === 'hash');
    expect(hashes.map((m) => m.id)).toEqual([1, 3]);
    expect(hashes[1]).toMatchObject({ hash: coldHash({ ...BASE, l1_length: 0.35 }) });
  });

  it('the hash waits for the deferred task, a newer request takes its place, an error pays it', () => {
    const sent: WorkerResponse[] = [];
    const tasks: (() => void)[] = [];
    const handle = createHandler(loadWasm(), (m) => sent.push(m), {
      defer: (task) => {
        tasks.push(task);
        return () => tasks.splice(tasks.indexOf(task), 1);
      },
    });
    handle({ type: 'generate', id: 1, params: BASE });
    expect(sent.map((m) => m.type)).toEqual(['result']);
    // A newer request before the hash ran: the first tree's hash is never computed.
    handle({ type: 'generate', id: 2, params: { ...BASE, seed: 5 } });
    expect(tasks).toHaveLength(1);
    // The next request fails: the tree on screen (id 2) still gets its hash.
    handle({ type: 'generate', id: 3, params: { ...BASE, scale: -1 } });
    expect(sent.map((m) => m.type)).toEqual(['result', 'result', 'hash', 'error']);
    expect(sent[2]).toEqual({ type: 'hash', id: 2, hash: coldHash({ ...BASE, seed: 5 }) });
    expect(tasks).toHaveLength(0);
  });

  it('results merge into whole trees equal to cold results, arrays shared', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: BASE });
    h.handle({ type: 'generate', id: 2, params: { ...BASE, foliage_angle: 10 } });
    const [first, second] = h.results();
    if (!first || !second) throw new Error('two results');
    const a: TreeBuffers = mergeUpdate(null, first);
    const b = mergeUpdate(a, second);
    expect(b.positions).toBe(a.positions);
    expect(b.foliage?.positions).toBe(a.foliage?.positions);
    expect(b.foliage?.matrices).not.toBe(a.foliage?.matrices);
    expect(b.foliage?.texture).toBeNull();
  });

  it('a primed session answers the first request with every array, and only once generated', () => {
    const h = harness(loadWasm(), { prime: BASE });
    h.handle({ type: 'generate', id: 1, params: BASE });
    const first = h.lastResult();
    expect(parts(first)).toEqual([
      'bark',
      'envelope',
      'markers',
      'instances',
      'leafMesh',
      'leafTexture',
      'shade',
    ]);
    expect(first.barkTextures).toBeDefined();
    // Nothing was regenerated for it: the primed tree is the requested one.
    expect(first.meta.changes).toEqual({
      skeleton: false,
      bark: false,
      placements: false,
      leaf_mesh: false,
      leaf: false,
      shade: false,
    });
    expect(h.tree().meta.hash).toBe(coldHash(BASE));
    // A different first tree after a warm-up is still right.
    const other = harness(loadWasm(), { prime: BASE });
    other.handle({ type: 'generate', id: 1, params: { ...BASE, seed: 8 } });
    expect(other.tree().meta.hash).toBe(coldHash({ ...BASE, seed: 8 }));
  });

  it('a primed session bakes its bark maps ahead, so the first request only copies arrays', () => {
    const real = loadWasm();
    let bakes = 0;
    const counting = {
      ...real,
      bark_maps: (kind: number, size: number) => {
        bakes++;
        return real.bark_maps!(kind, size);
      },
    } as typeof real;
    const h = harness(counting, { prime: BASE });
    expect(bakes).toBe(1);
    h.handle({ type: 'generate', id: 1, params: BASE });
    expect(bakes).toBe(1);
    const cold = harness();
    cold.handle({ type: 'generate', id: 1, params: BASE });
    const [got, want] = [h.lastResult().barkTextures, cold.lastResult().barkTextures];
    expect(got?.kind).toBe(want?.kind);
    expect(got?.color).toEqual(want?.color);
    expect(got?.orm).toEqual(want?.orm);
    // A first request with another bark type bakes its own maps.
    const other = harness(counting, { prime: BASE });
    other.handle({ type: 'generate', id: 1, params: { ...BASE, bark_type: 2 } });
    expect(other.lastResult().barkTextures?.kind).toBe(2);
  });
});
