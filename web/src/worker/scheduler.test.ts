/** Unit tests of the latest-wins scheduler with a fake worker factory. */
import { describe, expect, it } from 'vitest';
import type { SylvaError, TreeMeta } from '../core/types';
import type { ReadyInfo, ResultResponse, WorkerRequest, WorkerResponse } from './protocol';
import { GenerationScheduler, type SchedulerCallbacks, type WorkerFactory } from './scheduler';

/** A fake worker: records posts, lets the test push responses and error events. */
class FakeWorker {
  posted: WorkerRequest[] = [];
  terminated = false;
  constructor(
    readonly emit: (response: WorkerResponse) => void,
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

const META: TreeMeta = {
  vertices: 0,
  triangles: 0,
  hash: '0000000000000000',
  bounds: { min: [0, 0, 0], max: [1, 1, 1] },
  groups: [],
  stage_ms: {},
  total_ms: 1,
  stems: 0,
};

function result(id: number): ResultResponse {
  return {
    type: 'result',
    id,
    positions: new Float32Array(0),
    normals: new Float32Array(0),
    uvs: new Float32Array(0),
    indices: new Uint32Array(0),
    envelope: new Float32Array(0),
    meta: META,
  };
}

function setup() {
  const workers: FakeWorker[] = [];
  const factory: WorkerFactory = (onMessage, onError) => {
    const w = new FakeWorker(onMessage, onError);
    workers.push(w);
    return {
      post: (r) => w.posted.push(r),
      terminate: () => {
        w.terminated = true;
      },
    };
  };
  const log = {
    ready: [] as [ReadyInfo, number][],
    results: [] as number[],
    errors: [] as [SylvaError, number | null][],
    busy: [] as boolean[],
  };
  const callbacks: SchedulerCallbacks = {
    onReady: (info, restarts) => log.ready.push([info, restarts]),
    onResult: (r) => log.results.push(r.id),
    onError: (e, id) => log.errors.push([e, id]),
    onBusyChange: (b) => log.busy.push(b),
  };
  const scheduler = new GenerationScheduler(factory, callbacks);
  const current = (): FakeWorker => {
    const w = workers[workers.length - 1];
    if (!w) throw new Error('no worker');
    return w;
  };
  return { scheduler, workers, log, current };
}

describe('GenerationScheduler', () => {
  it('holds requests until the worker is ready, then sends only the latest', () => {
    const { scheduler, current } = setup();
    scheduler.request({ seed: 1 });
    const id2 = scheduler.request({ seed: 2 });
    expect(current().posted).toHaveLength(0);
    current().ready();
    expect(current().posted).toEqual([{ type: 'generate', id: id2, params: { seed: 2 } }]);
  });

  it('latest wins: 3 rapid requests post only the first and the last', () => {
    const { scheduler, current, log } = setup();
    current().ready();
    const a = scheduler.request({ seed: 1 });
    scheduler.request({ seed: 2 });
    const c = scheduler.request({ seed: 3 });
    expect(current().posted.map((r) => (r.type === 'generate' ? r.id : -1))).toEqual([a]);
    current().emit(result(a));
    expect(current().posted).toHaveLength(2);
    expect(current().posted[1]).toEqual({ type: 'generate', id: c, params: { seed: 3 } });
    current().emit(result(c));
    expect(log.results).toEqual([a, c]);
    expect(log.busy).toEqual([true, false]);
  });

  it('routes results by id and ignores unknown or stale ids', () => {
    const { scheduler, current, log } = setup();
    current().ready();
    const a = scheduler.request({ seed: 1 });
    current().emit(result(a + 100));
    expect(log.results).toEqual([]);
    current().emit(result(a));
    current().emit(result(a));
    expect(log.results).toEqual([a]);
  });

  it('reports typed errors with the request id and continues with the pending request', () => {
    const { scheduler, current, log } = setup();
    current().ready();
    const a = scheduler.request({ scale: -1 });
    const b = scheduler.request({ scale: 1 });
    const error: SylvaError = { kind: 'invalid_param', param: 'scale', message: 'scale: bad' };
    current().emit({ type: 'error', id: a, error });
    expect(log.errors).toEqual([[error, a]]);
    expect(current().lastGenerateId()).toBe(b);
  });

  it('on a panic recreates the worker and re-sends the newer pending request once', () => {
    const { scheduler, workers, current, log } = setup();
    current().ready();
    const a = scheduler.request({ seed: 1 });
    const b = scheduler.request({ seed: 2 });
    const first = current();
    first.emit({ type: 'fatal', message: 'panicked at boom' });
    expect(first.terminated).toBe(true);
    expect(workers).toHaveLength(2);
    expect(log.errors).toEqual([[{ kind: 'panic', message: 'panicked at boom' }, null]]);
    const second = current();
    expect(second.posted).toHaveLength(0);
    second.ready();
    expect(log.ready.map(([, restarts]) => restarts)).toEqual([0, 1]);
    expect(second.posted).toEqual([{ type: 'generate', id: b, params: { seed: 2 } }]);
    expect(second.posted.some((r) => r.type === 'generate' && r.id === a)).toBe(false);
    second.emit(result(b));
    expect(log.results).toEqual([b]);
    expect(second.posted).toHaveLength(1);
  });

  it('never re-sends the request that panicked (no resend loop)', () => {
    const { scheduler, workers, current, log } = setup();
    current().ready();
    scheduler.request({ seed: 666 });
    current().emit({ type: 'fatal', message: 'boom' });
    current().ready();
    expect(current().posted).toEqual([]);
    expect(workers).toHaveLength(2);
    expect(log.busy[log.busy.length - 1]).toBe(false);
  });

  it('a worker error event is treated like a panic', () => {
    const { scheduler, workers, current, log } = setup();
    current().ready();
    scheduler.request({ seed: 1 });
    current().fail('Uncaught RuntimeError: unreachable');
    expect(workers[0]?.terminated).toBe(true);
    expect(workers).toHaveLength(2);
    expect(log.errors[0]?.[0].kind).toBe('panic');
  });

  it('ignores messages from a terminated worker', () => {
    const { scheduler, workers, current, log } = setup();
    current().ready();
    const a = scheduler.request({ seed: 1 });
    current().emit({ type: 'fatal', message: 'boom' });
    workers[0]?.emit(result(a));
    workers[0]?.emit({ type: 'fatal', message: 'again' });
    expect(log.results).toEqual([]);
    expect(workers).toHaveLength(2);
  });

  it('a crash during start-up does not restart in a loop', () => {
    const { scheduler, workers, current, log } = setup();
    scheduler.request({ seed: 1 });
    current().emit({ type: 'fatal', message: 'wasm init failed' });
    expect(workers).toHaveLength(1);
    expect(log.errors[0]?.[0].kind).toBe('internal');
    expect(log.busy[log.busy.length - 1]).toBe(false);
  });

  it('debugPanic waits for the in-flight request, then the pending one survives the crash', () => {
    const { scheduler, current, log } = setup();
    current().ready();
    const a = scheduler.request({ seed: 1 });
    scheduler.debugPanic();
    const b = scheduler.request({ seed: 2 });
    expect(current().posted).toHaveLength(1);
    current().emit(result(a));
    expect(current().posted[1]).toEqual({ type: 'debug-panic' });
    current().emit({ type: 'fatal', message: 'intentional panic' });
    current().ready();
    expect(current().posted).toEqual([{ type: 'generate', id: b, params: { seed: 2 } }]);
    expect(log.errors.map(([e]) => e.message)).toEqual(['intentional panic']);
  });

  it('dispose terminates the worker and stops sending', () => {
    const { scheduler, current } = setup();
    current().ready();
    scheduler.dispose();
    expect(current().terminated).toBe(true);
    scheduler.request({ seed: 1 });
    expect(current().posted).toEqual([]);
  });
});
