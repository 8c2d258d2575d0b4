/** The LOD panel's latest-wins requests over the generation pool, with fake workers. */
import { describe, expect, it } from 'vitest';
import type { LodBuffers } from 'sylva-trees/worker';
import { GenerationPool } from '../pool/generationPool';
import { fakeWorkers } from '../testing/fakeWorker';
import { LodClient, SUPERSEDED } from './lodClient';

const lods = { levels: [] } as unknown as LodBuffers;

describe('LodClient', () => {
  it('starts a pool worker with the first request; a newer request rejects the waiting one', async () => {
    const { factory, workers, ready } = fakeWorkers();
    const pool = new GenerationPool(factory, 2);
    const client = new LodClient(pool);
    expect(workers).toHaveLength(0);
    const a = client.request({ seed: 1 });
    const b = client.request({ seed: 2 });
    const c = client.request({ seed: 3 }, []);
    await expect(b).rejects.toThrow(SUPERSEDED);
    // One request of the panel at a time, even with a second worker free.
    expect(workers).toHaveLength(1);
    ready();
    const worker = workers[0]!;
    expect(worker.posted).toEqual([{ type: 'lods', id: 1, params: { seed: 1 } }]);
    worker.emit({ type: 'lods', id: 1, lods });
    await expect(a).resolves.toBe(lods);
    expect(worker.posted.at(-1)).toEqual({ type: 'lods', id: 2, params: { seed: 3 } });
    worker.emit({ type: 'lods', id: 2, lods });
    await expect(c).resolves.toBe(lods);
    // Behind the exports that keep both workers busy, the panel's request waits in the pool's
    // queue, where a newer one replaces it.
    const exports = [pool.export({ seed: 8 }, [], 'glb'), pool.export({ seed: 9 }, [], 'obj')];
    expect(workers).toHaveLength(2);
    const d = client.request({ seed: 4 });
    expect(pool.state().waiting).toBe(1);
    const e = client.request({ seed: 5 });
    await expect(d).rejects.toThrow(SUPERSEDED);
    expect(pool.state().waiting).toBe(1);
    // A closed panel takes its waiting request out of the pool's queue.
    client.dispose();
    await expect(e).rejects.toThrow('the LOD request was cancelled');
    expect(pool.state().waiting).toBe(0);
    pool.dispose();
    for (const x of exports) await expect(x).rejects.toThrow('The export was cancelled.');
  });

  it('a crash rejects the request in flight with its message; the next request gets a fresh worker', async () => {
    const { factory, workers, ready } = fakeWorkers();
    const pool = new GenerationPool(factory, 1);
    const client = new LodClient(pool);
    const a = client.request({ seed: 1 });
    const b = client.request({ seed: 2 });
    ready();
    workers[0]!.emit({ type: 'fatal', message: 'boom' });
    await expect(a).rejects.toThrow('the generation worker crashed: boom');
    expect(workers).toHaveLength(2);
    ready();
    expect(workers[1]!.posted).toEqual([{ type: 'lods', id: 2, params: { seed: 2 } }]);
    workers[1]!.emit({ type: 'error', id: 2, error: { kind: 'internal', message: 'bad' } });
    await expect(b).rejects.toThrow('bad');
    pool.dispose();
  });
});
