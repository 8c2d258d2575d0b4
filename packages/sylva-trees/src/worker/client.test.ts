/** The worker-client base with a fake worker (no real Worker) and fake timers. */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { WorkerClient, type ClientOptions, type WorkerFactory } from './client';

type Req = { id: number };
type Res = { type: 'ready' } | { type: 'fatal'; message: string } | { type: 'done'; id: number };

/** A fake worker: what was posted to it, and a way to answer. */
interface Fake {
  posted: Req[];
  terminated: boolean;
  debug: boolean;
  emit(response: Res): void;
  fail(message: string): void;
}

function setup(options: ClientOptions = {}, limitMs?: (job: number) => number | undefined) {
  const workers: Fake[] = [];
  const factory: WorkerFactory<Req, Res> = (onMessage, onError, start) => {
    const fake: Fake = {
      posted: [],
      terminated: false,
      debug: start?.debug === true,
      emit: onMessage,
      fail: onError,
    };
    workers.push(fake);
    return { post: (r) => fake.posted.push(r), terminate: () => void (fake.terminated = true) };
  };
  const log = {
    ready: [] as number[],
    answered: [] as number[],
    crashes: [] as [string, number | null, boolean][],
    timeouts: [] as [number, number][],
    dropped: [] as [number, string][],
    busy: [] as boolean[],
  };
  const client = new WorkerClient<number, Req, Res>(
    factory,
    {
      message: (job) => ({ id: job }),
      ends: (response, job) => response.type === 'done' && response.id === job,
      receive: (_response, answered) => {
        if (answered !== null) log.answered.push(answered);
      },
      ready: (_response, restarts) => log.ready.push(restarts),
      crashed: (message, lost, starting) => log.crashes.push([message, lost, starting]),
      timedOut: (lost, limitMs) => log.timeouts.push([lost, limitMs]),
      dropped: (job, reason) => log.dropped.push([job, reason]),
      busy: (busy) => log.busy.push(busy),
      ...(limitMs ? { limitMs } : {}),
    },
    options,
  );
  const current = (): Fake => {
    const fake = workers.at(-1);
    if (!fake) throw new Error('no worker');
    return fake;
  };
  return { client, workers, current, log };
}

beforeEach(() => vi.useFakeTimers());
afterEach(() => vi.useRealTimers());

describe('WorkerClient', () => {
  it('waits for ready, then sends the latest request; superseded ones are dropped', () => {
    const { client, current, log } = setup();
    client.submit(1);
    client.submit(2);
    expect(current().posted).toEqual([]);
    expect(log.dropped).toEqual([[1, 'superseded']]);
    current().emit({ type: 'ready' });
    expect(current().posted).toEqual([{ id: 2 }]);
    client.submit(3);
    client.submit(4);
    current().emit({ type: 'done', id: 2 });
    expect(current().posted).toEqual([{ id: 2 }, { id: 4 }]);
    current().emit({ type: 'done', id: 4 });
    expect(log.answered).toEqual([2, 4]);
    expect(log.busy).toEqual([true, false]);
  });

  it('a queue keeps every request, in order', () => {
    const { client, current, log } = setup({ policy: 'queue' });
    current().emit({ type: 'ready' });
    [1, 2, 3].forEach((job) => client.submit(job));
    for (const id of [1, 2, 3]) current().emit({ type: 'done', id });
    expect(log.answered).toEqual([1, 2, 3]);
    expect(log.dropped).toEqual([]);
  });

  it('a crash of a ready worker reports the lost request and recreates the worker', () => {
    const { client, workers, current, log } = setup();
    current().emit({ type: 'ready' });
    client.submit(1);
    client.submit(2);
    current().emit({ type: 'fatal', message: 'boom' });
    expect(workers[0]?.terminated).toBe(true);
    expect(log.crashes).toEqual([['boom', 1, false]]);
    current().emit({ type: 'ready' });
    expect(log.ready).toEqual([0, 1]);
    expect(current().posted).toEqual([{ id: 2 }]);
    // The old worker's late words are ignored; an error event is a crash too.
    workers[0]?.emit({ type: 'done', id: 1 });
    current().fail('');
    expect(log.answered).toEqual([]);
    expect(log.crashes[1]).toEqual(['the worker failed', 2, false]);
    expect(workers).toHaveLength(3);
  });

  it('a crash while starting drops what waited, and only a new request starts again', () => {
    const { client, workers, current, log } = setup();
    client.submit(1);
    current().emit({ type: 'fatal', message: 'init failed' });
    expect(log.crashes).toEqual([['init failed', null, true]]);
    expect(log.dropped).toEqual([[1, 'failed-start']]);
    expect(workers).toHaveLength(1);
    expect(log.busy.at(-1)).toBe(false);
    client.submit(2);
    expect(workers).toHaveLength(2);
    current().emit({ type: 'ready' });
    expect(current().posted).toEqual([{ id: 2 }]);
  });

  it('a lazy client starts its worker with the first request and after a crash', () => {
    const { client, workers, current } = setup({ eager: false });
    expect(workers).toHaveLength(0);
    client.submit(1);
    expect(workers).toHaveLength(1);
    current().emit({ type: 'ready' });
    current().emit({ type: 'fatal', message: 'boom' });
    expect(workers).toHaveLength(1);
    client.submit(2);
    expect(workers).toHaveLength(2);
  });

  it('a request past the time limit stops the worker, which is recreated', () => {
    const { client, workers, current, log } = setup({ timeLimitMs: 1_000 });
    current().emit({ type: 'ready' });
    client.submit(1);
    vi.advanceTimersByTime(999);
    expect(log.timeouts).toEqual([]);
    client.timeLimitMs = 50; // applies to the next request
    vi.advanceTimersByTime(1);
    expect(log.timeouts).toEqual([[1, 1_000]]);
    expect(workers[0]?.terminated).toBe(true);
    expect(client.restarts).toBe(1);
    current().emit({ type: 'ready' });
    client.submit(2);
    vi.advanceTimersByTime(50);
    expect(log.timeouts).toEqual([
      [1, 1_000],
      [2, 50],
    ]);
  });

  it('a per-request limit (the hook) replaces the client-wide one', () => {
    // Odd jobs (exports) have a limit, even ones (levels of detail) none.
    const { client, current, log } = setup({ timeLimitMs: 10 }, (job) =>
      job % 2 === 1 ? 100 : undefined,
    );
    current().emit({ type: 'ready' });
    client.submit(2);
    vi.advanceTimersByTime(10_000);
    expect(log.timeouts).toEqual([]);
    current().emit({ type: 'done', id: 2 });
    client.submit(3);
    vi.advanceTimersByTime(99);
    expect(log.timeouts).toEqual([]);
    vi.advanceTimersByTime(1);
    expect(log.timeouts).toEqual([[3, 100]]);
  });

  it('a request sent first goes before the waiting ones', () => {
    const { client, current } = setup();
    current().emit({ type: 'ready' });
    client.submit(1);
    client.submit(2);
    client.submitFirst(9);
    current().emit({ type: 'done', id: 1 });
    current().emit({ type: 'done', id: 9 });
    expect(current().posted).toEqual([{ id: 1 }, { id: 9 }, { id: 2 }]);
  });

  it('stopInFlight drops the request in flight silently and starts a fresh worker', () => {
    const { client, workers, current, log } = setup();
    current().emit({ type: 'ready' });
    client.submit(1);
    expect(client.stopInFlight()).toBe(1);
    expect(workers).toHaveLength(2);
    expect(log.crashes).toEqual([]);
    expect(client.restarts).toBe(0);
    expect(log.busy.at(-1)).toBe(false);
  });

  it('dispose terminates the worker and drops every request not answered', () => {
    const { client, current, log } = setup({ policy: 'queue', timeLimitMs: 100 });
    current().emit({ type: 'ready' });
    client.submit(1);
    client.submit(2);
    client.dispose();
    expect(current().terminated).toBe(true);
    expect(log.dropped).toEqual([
      [1, 'disposed'],
      [2, 'disposed'],
    ]);
    client.submit(3);
    expect(log.dropped.at(-1)).toEqual([3, 'disposed']);
    expect(vi.getTimerCount()).toBe(0);
  });

  it('passes the start options to the factory', () => {
    const { current } = setup({ start: { debug: true } });
    expect(current().debug).toBe(true);
  });
});
