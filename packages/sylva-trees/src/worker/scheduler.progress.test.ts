/** Growth progress and Cancel in the scheduler (fake worker, fake timers). */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { SylvaError } from '../core/types';
import { GenerationScheduler } from './scheduler';
import { fakeWorkers, result } from './scheduler.fixtures';

beforeEach(() => vi.useFakeTimers());
afterEach(() => vi.useRealTimers());

function setup() {
  const { factory, workers, current } = fakeWorkers();
  const log = {
    progress: [] as [number | null, number | null][],
    results: [] as number[],
    errors: [] as SylvaError[],
    busy: [] as boolean[],
  };
  const scheduler = new GenerationScheduler(factory, {
    onReady: () => undefined,
    onResult: (r) => log.results.push(r.id),
    onError: (e) => log.errors.push(e),
    onBusyChange: (b) => log.busy.push(b),
    onProgress: (f, id) => log.progress.push([f, id]),
  });
  const ready = () => current().ready();
  return { scheduler, workers, log, current, ready };
}

describe('scheduler progress and cancel', () => {
  it('forwards progress of the in-flight request only, and clears it when done', () => {
    const { scheduler, current, ready, log } = setup();
    ready();
    const a = scheduler.request({ seed: 1 }, [
      { kind: 'sphere', group: 'crown', centre: [0, 5, 0], size: [2, 2, 2] },
    ]);
    expect(current().posted[0]).toMatchObject({ id: a, volumes: [{ kind: 'sphere' }] });
    current().emit({ type: 'progress', id: a, fraction: 0.25 });
    current().emit({ type: 'progress', id: a + 7, fraction: 0.5 });
    current().emit({ type: 'progress', id: a, fraction: 0.5 });
    current().emit(result(a));
    expect(log.progress).toEqual([
      [0.25, a],
      [0.5, a],
      [null, null],
    ]);
    expect(log.results).toEqual([a]);
  });

  it('cancel terminates the busy worker, starts a fresh one, reports no error, keeps results', () => {
    const { scheduler, workers, current, ready, log } = setup();
    ready();
    const a = scheduler.request({ seed: 1 });
    current().emit(result(a));
    const b = scheduler.request({ seed: 2 });
    scheduler.request({ seed: 3 }); // pending behind b: dropped too
    current().emit({ type: 'progress', id: b, fraction: 0.1 });
    expect(scheduler.cancel()).toBe(true);
    expect(workers).toHaveLength(2);
    expect(workers[0]!.terminated).toBe(true);
    expect(log.errors).toEqual([]);
    expect(log.busy[log.busy.length - 1]).toBe(false);
    expect(log.progress[log.progress.length - 1]).toEqual([null, null]);
    // A late answer from the dead worker is ignored; the fresh worker serves new requests.
    workers[0]!.emit(result(b));
    expect(log.results).toEqual([a]);
    ready();
    const c = scheduler.request({ seed: 4 });
    expect(current().posted).toEqual([{ type: 'generate', id: c, params: { seed: 4 } }]);
    expect(scheduler.cancel()).toBe(true);
    expect(scheduler.cancel()).toBe(false);
  });
});
