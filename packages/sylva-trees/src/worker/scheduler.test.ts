/** Unit tests of the latest-wins scheduler with a fake worker factory (and fake timers). */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { SylvaError } from '../core/types';
import type { ReadyInfo } from './protocol';
import { fakeWorkers, result } from './scheduler.fixtures';
import {
  DEFAULT_TIME_LIMIT_MS,
  GenerationScheduler,
  type SchedulerCallbacks,
  type SchedulerOptions,
} from './scheduler';

beforeEach(() => {
  vi.useFakeTimers();
});

afterEach(() => {
  vi.useRealTimers();
});

function setup(options?: SchedulerOptions) {
  const { factory, workers, current } = fakeWorkers();
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
  const scheduler = new GenerationScheduler(factory, callbacks, options);
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

  it('hands on the export formats of the ready message (export workers run the same core)', () => {
    const { current, log } = setup();
    current().emit({
      type: 'ready',
      registry: [],
      presets: [],
      version: 'test',
      exportFormats: ['glb', 'obj'],
      leafPresets: [],
    });
    expect(log.ready).toEqual([
      [
        { registry: [], presets: [], version: 'test', threads: 1, exportFormats: ['glb', 'obj'] },
        0,
      ],
    ]);
  });

  it('hands on the threads of the ready message (2: the threaded core and its helper)', () => {
    const { current, log } = setup();
    current().emit({ type: 'ready', registry: [], presets: [], version: 'test', threads: 2 });
    expect(log.ready).toEqual([[{ registry: [], presets: [], version: 'test', threads: 2 }, 0]]);
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

  it('debug hooks need a debug scheduler, whose workers start with the debug flag', () => {
    const plain = setup();
    expect(plain.current().debug).toBe(false);
    expect(() => plain.scheduler.debugPanic()).toThrow(/debug: true/);
    expect(() => plain.scheduler.debugHang(5)).toThrow(/debug: true/);
    plain.current().ready();
    expect(plain.current().posted).toEqual([]);
    const debug = setup({ debug: true });
    expect(debug.current().debug).toBe(true);
    debug.current().emit({ type: 'fatal', message: 'boom' });
    debug.scheduler.request({ seed: 1 });
    expect(debug.current().debug).toBe(true);
  });

  it('debugPanic waits for the in-flight request, then the pending one survives the crash', () => {
    const { scheduler, current, log } = setup({ debug: true });
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

  it('a worker crash from an OOM-like trap (no panic text) is handled like a panic', () => {
    const { scheduler, workers, current, log } = setup();
    current().ready();
    scheduler.request({ seed: 1 });
    const b = scheduler.request({ seed: 2 });
    current().emit({
      type: 'fatal',
      message: 'WebAssembly trap (memory access out of bounds): the generator aborted',
    });
    expect(workers[0]?.terminated).toBe(true);
    expect(log.errors).toEqual([
      [
        {
          kind: 'panic',
          message: 'WebAssembly trap (memory access out of bounds): the generator aborted',
        },
        null,
      ],
    ]);
    current().ready();
    expect(current().posted).toEqual([{ type: 'generate', id: b, params: { seed: 2 } }]);
    // An uncaught RuntimeError surfacing as the worker's error event takes the same path.
    current().fail('Uncaught RuntimeError: memory access out of bounds');
    expect(workers).toHaveLength(3);
    expect(log.errors[1]?.[0]).toEqual({
      kind: 'panic',
      message: 'Uncaught RuntimeError: memory access out of bounds',
    });
  });

  it('dispose clears the time limit', () => {
    const { scheduler, current, log } = setup();
    current().ready();
    scheduler.request({ seed: 1 });
    scheduler.dispose();
    vi.advanceTimersByTime(DEFAULT_TIME_LIMIT_MS * 2);
    expect(log.errors).toEqual([]);
    expect(vi.getTimerCount()).toBe(0);
  });
});

describe('GenerationScheduler time limit', () => {
  it('stops a generation that runs past 10 s: terminate, report, recreate', () => {
    const { scheduler, workers, current, log } = setup();
    expect(scheduler.timeLimitMs).toBe(10_000);
    current().ready();
    const a = scheduler.request({ seed: 1 });
    vi.advanceTimersByTime(9_999);
    expect(workers[0]?.terminated).toBe(false);
    expect(log.errors).toEqual([]);
    vi.advanceTimersByTime(1);
    expect(workers[0]?.terminated).toBe(true);
    expect(workers).toHaveLength(2);
    expect(log.errors).toHaveLength(1);
    const [error, id] = log.errors[0] ?? [];
    expect(id).toBe(a);
    expect(error?.kind).toBe('timeout');
    expect(error?.message).toMatch(/longer than 10 s and was stopped/);
    expect(error?.message).toMatch(/previous tree is kept/);
    expect(log.results).toEqual([]);
    expect(log.busy).toEqual([true, false]);
    // The new worker starts idle: the request that timed out is never re-sent.
    current().ready();
    expect(log.ready.map(([, restarts]) => restarts)).toEqual([0, 1]);
    expect(current().posted).toEqual([]);
    expect(scheduler.restartCount).toBe(1);
  });

  it('the newer pending request goes to the recreated worker', () => {
    const { scheduler, current, log } = setup();
    current().ready();
    const a = scheduler.request({ seed: 1 });
    const b = scheduler.request({ seed: 2 });
    vi.advanceTimersByTime(DEFAULT_TIME_LIMIT_MS);
    expect(log.errors[0]?.[1]).toBe(a);
    expect(log.busy[log.busy.length - 1]).toBe(true);
    current().ready();
    expect(current().posted).toEqual([{ type: 'generate', id: b, params: { seed: 2 } }]);
    current().emit(result(b));
    expect(log.results).toEqual([b]);
    expect(log.busy[log.busy.length - 1]).toBe(false);
  });

  it('every request gets the whole limit, counted from when it is sent', () => {
    const { scheduler, current, log } = setup();
    current().ready();
    const a = scheduler.request({ seed: 1 });
    const b = scheduler.request({ seed: 2 });
    vi.advanceTimersByTime(9_000);
    current().emit(result(a));
    expect(current().lastGenerateId()).toBe(b);
    vi.advanceTimersByTime(9_000);
    expect(log.errors).toEqual([]);
    current().emit(result(b));
    vi.advanceTimersByTime(60_000);
    expect(log.errors).toEqual([]);
    expect(log.results).toEqual([a, b]);
    expect(vi.getTimerCount()).toBe(0);
  });

  it('the time before the worker is ready does not count', () => {
    const { scheduler, current, log } = setup();
    const a = scheduler.request({ seed: 1 });
    vi.advanceTimersByTime(DEFAULT_TIME_LIMIT_MS * 3);
    expect(log.errors).toEqual([]);
    current().ready();
    vi.advanceTimersByTime(DEFAULT_TIME_LIMIT_MS - 1);
    current().emit(result(a));
    expect(log.results).toEqual([a]);
    expect(log.errors).toEqual([]);
  });

  it('a late answer from the stopped worker is ignored', () => {
    const { scheduler, workers, current, log } = setup();
    current().ready();
    const a = scheduler.request({ seed: 1 });
    vi.advanceTimersByTime(DEFAULT_TIME_LIMIT_MS);
    workers[0]?.emit(result(a));
    workers[0]?.emit({ type: 'fatal', message: 'late' });
    expect(log.results).toEqual([]);
    expect(log.errors.map(([e]) => e.kind)).toEqual(['timeout']);
    expect(workers).toHaveLength(2);
    expect(current().terminated).toBe(false);
  });

  it('the limit is configurable, per scheduler and at run time', () => {
    const { scheduler, current, log } = setup({ timeLimitMs: 2_500 });
    current().ready();
    scheduler.request({ seed: 1 });
    vi.advanceTimersByTime(2_500);
    expect(log.errors[0]?.[0].message).toMatch(/longer than 2\.5 s/);
    expect(log.errors[0]?.[0].message).toMatch(/fewer Levels or Branches/);
    current().ready();
    scheduler.timeLimitMs = 500;
    scheduler.request({ seed: 2 });
    vi.advanceTimersByTime(499);
    expect(log.errors).toHaveLength(1);
    vi.advanceTimersByTime(1);
    expect(log.errors).toHaveLength(2);
    expect(() => (scheduler.timeLimitMs = 0)).toThrow(RangeError);
    expect(() => (scheduler.timeLimitMs = Number.NaN)).toThrow(RangeError);
    expect(() => setup({ timeLimitMs: -1 })).toThrow(RangeError);
  });

  it("a grown tree's timeout advice names growth's parameters", () => {
    const { scheduler, current, log } = setup();
    current().ready();
    scheduler.request({ growth_mode: 1, markers: 50_000 });
    vi.advanceTimersByTime(DEFAULT_TIME_LIMIT_MS);
    const message = log.errors[0]?.[0].message ?? '';
    expect(message).toMatch(/fewer Markers, Extra Markers or Iterations, a longer Internode/);
    expect(message).not.toMatch(/Levels/);
  });

  it('debugHang: a short hang ends with idle, a long one is stopped by the limit', () => {
    const { scheduler, workers, current, log } = setup({ debug: true });
    current().ready();
    scheduler.debugHang(100);
    expect(current().posted).toEqual([{ type: 'debug-hang', ms: 100 }]);
    const b = scheduler.request({ seed: 2 });
    current().emit({ type: 'idle' });
    expect(current().lastGenerateId()).toBe(b);
    current().emit(result(b));
    scheduler.debugHang(60_000);
    const c = scheduler.request({ seed: 3 });
    vi.advanceTimersByTime(DEFAULT_TIME_LIMIT_MS);
    expect(workers[0]?.terminated).toBe(true);
    expect(log.errors).toEqual([[expect.objectContaining({ kind: 'timeout' }), null]]);
    current().ready();
    expect(current().posted).toEqual([{ type: 'generate', id: c, params: { seed: 3 } }]);
  });
});
