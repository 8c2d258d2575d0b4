/** The LOD client over the worker-client base, with a fake worker. */
import { describe, expect, it } from 'vitest';
import type { LodBuffers } from 'sylva-trees/worker';
import { fakeWorkers } from '../testing/fakeWorker';
import { LodClient, SUPERSEDED } from './lodClient';

describe('LodClient', () => {
  it('starts with the first request; a newer request rejects the waiting one; dispose rejects', async () => {
    const { factory, workers, ready } = fakeWorkers();
    const client = new LodClient(factory);
    expect(workers).toHaveLength(0);
    const a = client.request({ seed: 1 });
    const b = client.request({ seed: 2 });
    const c = client.request({ seed: 3 }, []);
    await expect(a).rejects.toThrow(SUPERSEDED);
    await expect(b).rejects.toThrow(SUPERSEDED);
    ready();
    const worker = workers[0]!;
    expect(worker.posted).toEqual([{ type: 'lods', id: 3, params: { seed: 3 } }]);
    const lods = { levels: [] } as unknown as LodBuffers;
    worker.emit({ type: 'lods', id: 3, lods });
    await expect(c).resolves.toBe(lods);
    const d = client.request({ seed: 4 });
    client.dispose();
    await expect(d).rejects.toThrow(/disposed/);
  });

  it('a crash rejects the request in flight with its message', async () => {
    const { factory, workers, ready } = fakeWorkers();
    const client = new LodClient(factory, false);
    const a = client.request({ seed: 1 });
    const b = client.request({ seed: 2 });
    ready();
    workers[0]!.emit({ type: 'fatal', message: 'boom' });
    await expect(a).rejects.toThrow('boom');
    expect(workers).toHaveLength(2);
    ready();
    expect(workers[1]!.posted).toEqual([{ type: 'lods', id: 2, params: { seed: 2 } }]);
    workers[1]!.emit({ type: 'error', id: 2, error: { kind: 'internal', message: 'bad' } });
    await expect(b).rejects.toThrow('bad');
  });
});
