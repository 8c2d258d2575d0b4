/** The scheduler's drag handling: interactive requests allow a preview, the full tree follows. */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { fakeWorkers, result } from './scheduler.fixtures';
import { GenerationScheduler, SETTLE_MS, type SchedulerRequest } from './scheduler';

beforeEach(() => {
  vi.useFakeTimers();
});

afterEach(() => {
  vi.useRealTimers();
});

function setup() {
  const { factory, current } = fakeWorkers();
  const log = { results: [] as number[], hashes: [] as [string, number][] };
  const scheduler = new GenerationScheduler(factory, {
    onReady: () => undefined,
    onResult: (r) => log.results.push(r.id),
    onHash: (hash, id) => log.hashes.push([hash, id]),
    onError: () => undefined,
    onBusyChange: () => undefined,
  });
  current().ready();
  return { scheduler, current, log };
}

const generates = (posted: SchedulerRequest[]) =>
  posted.flatMap((p) => (p.type === 'generate' ? [p] : []));

describe('GenerationScheduler drags', () => {
  it('marks interactive requests as previews and requests the full tree when settled', () => {
    const { scheduler, current } = setup();
    const a = scheduler.request({ l1_length: 0.31 }, undefined, { interactive: true });
    expect(current().posted.at(-1)).toEqual({
      type: 'generate',
      id: a,
      params: { l1_length: 0.31 },
      preview: true,
    });
    current().emit(result(a));
    const b = scheduler.settle();
    expect(b).not.toBeNull();
    expect(current().posted.at(-1)).toEqual({
      type: 'generate',
      id: b,
      params: { l1_length: 0.31 },
    });
    // Settled once: nothing left to settle.
    current().emit(result(b ?? -1));
    expect(scheduler.settle()).toBeNull();
  });

  it('settles by itself after a pause without input, and only once', () => {
    const { scheduler, current } = setup();
    const a = scheduler.request({ seed: 1 }, undefined, { interactive: true });
    current().emit(result(a));
    vi.advanceTimersByTime(SETTLE_MS - 1);
    expect(generates(current().posted)).toHaveLength(1);
    const b = scheduler.request({ seed: 2 }, undefined, { interactive: true });
    vi.advanceTimersByTime(SETTLE_MS - 1); // the new input restarted the wait
    current().emit(result(b));
    expect(generates(current().posted)).toHaveLength(2);
    vi.advanceTimersByTime(1);
    const posted = generates(current().posted);
    expect(posted).toHaveLength(3);
    expect(posted[2]).toEqual(expect.objectContaining({ params: { seed: 2 } }));
    expect(posted[2]?.preview).toBeUndefined();
    vi.advanceTimersByTime(10 * SETTLE_MS);
    expect(generates(current().posted)).toHaveLength(3);
  });

  it('a plain request cancels the pending settle (it is full already)', () => {
    const { scheduler, current } = setup();
    const a = scheduler.request({ seed: 1 }, undefined, { interactive: true });
    current().emit(result(a));
    const b = scheduler.request({ seed: 3 });
    current().emit(result(b));
    vi.advanceTimersByTime(SETTLE_MS * 2);
    expect(scheduler.settle()).toBeNull();
    expect(generates(current().posted)).toHaveLength(2);
  });

  it('delivers the hash of the last result only', () => {
    const { scheduler, current, log } = setup();
    const a = scheduler.request({ seed: 1 });
    current().emit(result(a));
    const b = scheduler.request({ seed: 2 });
    current().emit({ type: 'hash', id: a, hash: 'aaaa' }); // a's hash after b was sent: still a's tree
    current().emit(result(b));
    current().emit({ type: 'hash', id: a, hash: 'late' }); // stale
    current().emit({ type: 'hash', id: b, hash: 'bbbb' });
    expect(log.hashes).toEqual([
      ['aaaa', a],
      ['bbbb', b],
    ]);
  });
});
