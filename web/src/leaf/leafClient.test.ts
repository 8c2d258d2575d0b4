/** The leaf client over the worker-client base, with a fake worker. */
import { describe, expect, it } from 'vitest';
import { fakeWorkers } from '../testing/fakeWorker';
import { LeafClient } from './leafClient';

describe('LeafClient', () => {
  it('sends the latest request when ready and delivers leaves, presets and crashes', () => {
    const { factory, workers, ready } = fakeWorkers();
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
