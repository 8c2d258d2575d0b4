/** The leaf and LOD clients over the worker-client base, with a fake worker. */
import { describe, expect, it } from 'vitest';
import { LeafClient } from '../leaf/leafClient';
import { LodClient, SUPERSEDED } from '../lod/lodClient';
import type { LodBuffers } from '../../../packages/sylva-trees/src/lod/types';
import type {
  GeneratorWorkerFactory,
  WorkerRequest,
  WorkerResponse,
} from '../../../packages/sylva-trees/src/worker/protocol';

function fakes() {
  const workers: { posted: WorkerRequest[]; emit: (r: WorkerResponse) => void }[] = [];
  const factory: GeneratorWorkerFactory = (onMessage) => {
    const fake = { posted: [] as WorkerRequest[], emit: onMessage };
    workers.push(fake);
    return { post: (r) => fake.posted.push(r), terminate: () => undefined };
  };
  const ready = (): void =>
    workers.at(-1)?.emit({ type: 'ready', registry: [], presets: [], version: 't' });
  return { factory, workers, ready };
}

describe('LodClient', () => {
  it('starts with the first request; a newer request rejects the waiting one; dispose rejects', async () => {
    const { factory, workers, ready } = fakes();
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
    const { factory, workers, ready } = fakes();
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

describe('LeafClient', () => {
  it('sends the latest request when ready and delivers leaves, presets and crashes', () => {
    const { factory, workers, ready } = fakes();
    const log: string[] = [];
    const client = new LeafClient(factory, {
      onLeaf: (leaf, id) => log.push(`leaf ${id} ${leaf.svg}`),
      onError: (error) => log.push(`${error.kind} ${error.message}`),
      onPresets: (presets) => log.push(`presets ${presets.length}`),
    });
    client.request({}, -1, false);
    const b = client.request({}, 3, true);
    ready();
    const worker = workers[0]!;
    expect(worker.posted).toEqual([
      { type: 'leaf', id: b, params: {}, step: 3, triangulation: true },
    ]);
    const counts = { iterations: 1, nodes: 2, links: 1, segments: 1, auxins: 0, triangles: 4 };
    worker.emit({ type: 'leaf', id: b, svg: '<svg/>', hash: 'h', ...counts });
    worker.emit({ type: 'fatal', message: 'boom' });
    expect(log).toEqual(['presets 0', `leaf ${b} <svg/>`, 'panic boom']);
    expect(workers).toHaveLength(2);
    client.dispose();
  });
});
