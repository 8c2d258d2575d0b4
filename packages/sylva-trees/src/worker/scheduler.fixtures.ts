/** Test fixtures for the scheduler: a fake worker factory and empty results (no real Worker). */
import type { TreeMeta } from '../core/types';
import type { ResultResponse } from './protocol';
import type { GeneratorFactory, SchedulerRequest, SchedulerResponse } from './scheduler';

/** A fake worker: records posts, lets the test push responses and error events. */
export class FakeWorker {
  posted: SchedulerRequest[] = [];
  terminated = false;
  /** Started with the debug flag. */
  debug = false;
  constructor(
    readonly emit: (response: SchedulerResponse) => void,
    readonly fail: (message: string) => void,
  ) {}
  ready(): void {
    this.emit({ type: 'ready', registry: [], presets: [], version: 'test' });
  }
  lastGenerateId(): number {
    const last = this.posted[this.posted.length - 1];
    if (last?.type !== 'generate') throw new Error('last post is not a generate');
    return last.id;
  }
}

/** A factory that makes [`FakeWorker`]s, and the list of those made so far (oldest first). */
export function fakeWorkers(): {
  factory: GeneratorFactory;
  workers: FakeWorker[];
  current: () => FakeWorker;
} {
  const workers: FakeWorker[] = [];
  const factory: GeneratorFactory = (onMessage, onError, options) => {
    const w = new FakeWorker(onMessage, onError);
    w.debug = options?.debug === true;
    workers.push(w);
    return {
      post: (r) => w.posted.push(r),
      terminate: () => {
        w.terminated = true;
      },
    };
  };
  const current = (): FakeWorker => {
    const w = workers[workers.length - 1];
    if (!w) throw new Error('no worker');
    return w;
  };
  return { factory, workers, current };
}

const META: TreeMeta = {
  vertices: 0,
  triangles: 0,
  hash: '0000000000000000',
  bounds: { min: [0, 0, 0], max: [1, 1, 1] },
  groups: [],
  stage_ms: {},
  total_ms: 1,
  stems: 0,
  holes: 0,
  envelope: [],
  leaves: 0,
  leaf_hash: '0000000000000000',
  leaf_texture: null,
  bark_type: 0,
};

/** An empty result for request `id`. */
export function result(id: number): ResultResponse {
  return {
    type: 'result',
    id,
    bark: {
      positions: new Float32Array(0),
      normals: new Float32Array(0),
      uvs: new Float32Array(0),
      indices: new Uint32Array(0),
      wind: new Float32Array(0),
    },
    envelope: new Float32Array(0),
    meta: META,
  };
}
