/**
 * The studio's generation pool: exports run on a pool worker, never the editor's, which answers
 * a drag while an export runs; an export through the pool is the same bytes as through the
 * export client of before (the real core, in process); a crashed pool worker rejects its job and
 * is restarted.
 */
import { describe, expect, it, vi } from 'vitest';
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';
import { inProcessFactory } from 'sylva-trees/testing';
import {
  EXPORT_TIME_LIMIT_MS,
  ExportClient,
  exportRequest,
  type ExportResponse,
  GenerationScheduler,
  type GeneratorWorkerFactory,
  type LodBuffers,
  type ResultResponse,
} from 'sylva-trees/worker';
import { MESH_EXPORTS, runMeshExport, type ExportSource } from '../export/meshExport';
import { fakeWorkers } from '../testing/fakeWorker';
import { GenerationPool } from './generationPool';

/** The file of an export, as bytes. */
async function bytesOf(response: ExportResponse): Promise<Uint8Array> {
  const [file] = response.files;
  if (!file) throw new Error('no file');
  return 'blob' in file ? new Uint8Array(await file.blob.arrayBuffer()) : file.bytes;
}

/** `inProcessFactory`, counting the workers it starts and what each was asked. */
function counted(): { factory: GeneratorWorkerFactory; asked: string[][] } {
  const asked: string[][] = [];
  const factory: GeneratorWorkerFactory = (onMessage, onError) => {
    const mine: string[] = [];
    asked.push(mine);
    const handle = inProcessFactory(onMessage, onError);
    return {
      post: (request) => {
        mine.push(request.type);
        handle.post(request);
      },
      terminate: () => handle.terminate(),
    };
  };
  return { factory, asked };
}

const SMALL: Params = { levels: 2, l1_branches: 8, leaves: 4 };

describe('GenerationPool', () => {
  it('runs an export on a pool worker; the editor worker answers a drag meanwhile', async () => {
    const editor = fakeWorkers();
    const results: number[] = [];
    const scheduler = new GenerationScheduler(editor.factory, {
      onReady: () => undefined,
      onResult: (r) => results.push(r.id),
      onError: () => undefined,
      onBusyChange: () => undefined,
    });
    editor.ready();
    const poolWorkers = fakeWorkers();
    const pool = new GenerationPool(poolWorkers.factory, 2);
    expect(poolWorkers.workers).toHaveLength(0); // started with the first job

    const params: Params = { seed: 5, season: 7 };
    const volumes: VolumePrimitive[] = [
      { kind: 'sphere', group: 'crown', centre: [0, 5, 0], size: [2, 2, 2] },
    ];
    const edits: Edit[] = [{ op: 'cut', at: [0, 3, 0] }];
    const item = MESH_EXPORTS.find((m) => m.testId === 'export-glb-baked')!;
    const source: ExportSource = {
      params,
      volumes,
      edits,
      name: 'tree',
      lod: null,
      generator: 'Sylva t',
    };
    const exporting = runMeshExport(pool, item, source);
    expect(poolWorkers.workers).toHaveLength(1);
    poolWorkers.ready();
    // The pool worker got the very request the export client writes, inputs and all.
    expect(poolWorkers.workers[0]!.posted).toEqual([
      exportRequest(1, params, volumes, 'glb', { name: 'tree', edits, leaves: 'baked' }),
    ]);
    expect(pool.state()).toMatchObject({ started: 1, load: [1, 0], given: { export: 1 } });

    // A drag while the export runs: the editor's worker gets it and answers it.
    const id = scheduler.request({ seed: 6 });
    expect(editor.workers[0]!.posted).toEqual([{ type: 'generate', id, params: { seed: 6 } }]);
    editor.workers[0]!.emit({ type: 'result', id, meta: {} } as unknown as ResultResponse);
    expect(results).toEqual([id]);
    let settled = false;
    void exporting.finally(() => (settled = true));
    await Promise.resolve();
    expect(settled).toBe(false);

    const answer: ExportResponse = {
      type: 'exported',
      id: 1,
      format: 'glb',
      hash: 'h',
      files: [{ name: 'tree.glb', mime: 'model/gltf-binary', bytes: new Uint8Array([1]) }],
    };
    poolWorkers.workers[0]!.emit(answer);
    await expect(exporting).resolves.toBe(answer);
    // The editor's worker was never asked for an export.
    expect(editor.workers.flatMap((w) => w.posted.map((r) => r.type))).toEqual(['generate']);
    scheduler.dispose();
    pool.dispose();
  });

  it('exports the same bytes as the export client, with the params, volumes, edits and season', async () => {
    const pool = counted();
    const generation = new GenerationPool(pool.factory, 2);
    const reference = new ExportClient(inProcessFactory);
    const volumes: VolumePrimitive[] = [
      { kind: 'sphere', group: 'crown', centre: [1, 6, 0], size: [2.5, 2.5, 2.5] },
    ];
    // Grown with the custom crown volume (the sphere changes the tree; handler.progress.test.ts).
    const grown: Params = {
      growth_mode: 1,
      iterations: 300,
      markers: 800,
      extra_markers: 300,
      crown_volume: 2,
    };
    // Each case differs from another by one input: the season, an edit, the volumes.
    const cases: { params: Params; volumes: VolumePrimitive[]; edits: Edit[] }[] = [
      { params: { ...SMALL, seed: 3 }, volumes: [], edits: [] },
      { params: { ...SMALL, seed: 3, season: 3 }, volumes: [], edits: [] },
      {
        params: { ...SMALL, seed: 3, season: 3 },
        volumes: [],
        edits: [{ op: 'bend', at: [0, 2, 0], to: [0.5, 2, 0] }],
      },
      { params: grown, volumes: [], edits: [] },
      { params: grown, volumes, edits: [] },
    ];
    const hashes = new Set<string>();
    for (const { params, volumes: v, edits } of cases) {
      for (const item of MESH_EXPORTS.filter((m) => m.format === 'glb' || m.format === 'obj')) {
        const source = { params, volumes: v, edits, name: 'tree', lod: null, generator: 'g' };
        const viaPool = await runMeshExport(generation, item, source);
        // What the Export menu asked the export worker for before the pool.
        const before = await reference.export(params, v, item.format, {
          name: 'tree',
          edits,
          ...(item.leaves ? { leaves: item.leaves } : {}),
          ...(item.strict ? { strict: item.strict } : {}),
        });
        expect(viaPool.hash).toBe(before.hash);
        expect(viaPool.files.map((f) => f.name)).toEqual(before.files.map((f) => f.name));
        const [got, want] = [await bytesOf(viaPool), await bytesOf(before)];
        expect(got.length).toBe(want.length);
        // Compared as one Buffer (an element-wise toEqual of megabytes takes minutes).
        expect(Buffer.from(got).equals(Buffer.from(want))).toBe(true);
        hashes.add(viaPool.hash);
      }
    }
    // Every input reaches the core: as many different trees as cases.
    expect(hashes.size).toBe(cases.length);
    // One job at a time here: one pool worker started, asked for exports only.
    expect(pool.asked).toEqual([Array(cases.length * 4).fill('export')]);
    reference.dispose();
    generation.dispose();
  }, 60_000);

  it('serves levels of detail with the leaves baked on request, in order, on free workers', async () => {
    const { factory, workers } = fakeWorkers();
    const pool = new GenerationPool(factory, 2);
    const a = pool.lods({ seed: 1 });
    const b = pool.lods({ seed: 2 }, undefined, undefined, { bakeLeaves: true });
    const waiting = new AbortController();
    const c = pool.lods({ seed: 3 }, undefined, undefined, { signal: waiting.signal });
    expect(workers).toHaveLength(2);
    for (const w of workers) w.emit({ type: 'ready', registry: [], presets: [], version: 't' });
    expect(workers[0]!.posted).toEqual([{ type: 'lods', id: 1, params: { seed: 1 } }]);
    expect(workers[1]!.posted).toEqual([
      { type: 'lods', id: 1, params: { seed: 2 }, bakeLeaves: true },
    ]);
    expect(pool.state().waiting).toBe(1);
    waiting.abort();
    await expect(c).rejects.toThrow('cancelled');
    const lods = { levels: [] } as unknown as LodBuffers;
    workers[1]!.emit({ type: 'lods', id: 1, lods });
    await expect(b).resolves.toBe(lods);
    pool.dispose();
    await expect(a).rejects.toThrow('the generation worker was disposed');
  });

  it('a crashed pool worker rejects its job with a clear message and is restarted', async () => {
    const { factory, workers, ready } = fakeWorkers();
    const pool = new GenerationPool(factory, 1);
    const exporting = pool.export({ seed: 1 }, [], 'glb');
    const next = pool.lods({ seed: 2 });
    ready();
    workers[0]!.emit({ type: 'fatal', message: 'RuntimeError: unreachable' });
    await expect(exporting).rejects.toThrow('The exporter crashed: RuntimeError: unreachable');
    // A fresh worker takes the next job.
    expect(workers).toHaveLength(2);
    ready();
    expect(workers[1]!.posted).toEqual([{ type: 'lods', id: 2, params: { seed: 2 } }]);
    workers[1]!.emit({ type: 'fatal', message: 'out of memory' });
    await expect(next).rejects.toThrow('the generation worker crashed: out of memory');
    pool.dispose();
  });

  it('stops an export past its time limit (not a level-of-detail job) and restarts the worker', async () => {
    vi.useFakeTimers();
    try {
      const { factory, workers, ready } = fakeWorkers();
      const pool = new GenerationPool(factory, 1);
      const baking = pool.lods({ seed: 1 });
      ready();
      vi.advanceTimersByTime(EXPORT_TIME_LIMIT_MS * 2);
      workers[0]!.emit({ type: 'lods', id: 1, lods: { levels: [] } as unknown as LodBuffers });
      await expect(baking).resolves.toBeTruthy();
      const exporting = pool.export({ seed: 1 }, [], 'obj');
      vi.advanceTimersByTime(EXPORT_TIME_LIMIT_MS);
      await expect(exporting).rejects.toThrow('The export took longer than 60 s.');
      expect(workers).toHaveLength(1);
      const next = pool.lods({ seed: 2 });
      expect(workers).toHaveLength(2);
      ready();
      expect(workers[1]!.posted).toEqual([{ type: 'lods', id: 3, params: { seed: 2 } }]);
      pool.dispose();
      await expect(next).rejects.toThrow('disposed');
    } finally {
      vi.useRealTimers();
    }
  });
});
