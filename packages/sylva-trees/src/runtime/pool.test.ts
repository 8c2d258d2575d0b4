import { describe, expect, it } from 'vitest';
import { LatestLane, poolSize, WorkerPool } from './pool';

/** A member whose jobs settle when the test says. */
class Member {
  disposed = false;
  readonly pending: { value: string; settle: (ok: boolean) => void }[] = [];
  constructor(readonly index: number) {}
  job(value = String(this.index)): Promise<string> {
    return new Promise((resolve, reject) =>
      this.pending.push({
        value,
        settle: (ok) => (ok ? resolve(`${value}@${this.index}`) : reject(new Error('crashed'))),
      }),
    );
  }
  /** Settles the oldest job (`ok` false: rejects it). */
  finish(ok = true): void {
    this.pending.shift()!.settle(ok);
  }
  dispose(): void {
    this.disposed = true;
  }
}

function pool(size: number) {
  const made: Member[] = [];
  const p = new WorkerPool((i) => {
    const m = new Member(i);
    made.push(m);
    return m;
  }, size);
  return { pool: p, made };
}

/** Lets settled promises run their callbacks. */
const tick = () => new Promise((resolve) => setTimeout(resolve, 0));

describe('poolSize', () => {
  it('is the core count within 1..4', () => {
    expect(poolSize(2)).toBe(2);
    expect(poolSize(16)).toBe(4);
    expect(poolSize(0)).toBe(1);
    expect(poolSize(undefined)).toBe(1);
    expect(poolSize(Number.NaN)).toBe(1);
    expect(poolSize(8, 6)).toBe(6);
  });
});

describe('WorkerPool', () => {
  it('makes members lazily and runs one job per member; the rest wait in order for a free one', async () => {
    const { pool: p, made } = pool(2);
    expect(p.started).toBe(0);
    const a = p.run((m) => m.job('a'));
    expect(made.map((m) => m.index)).toEqual([0]);
    const b = p.run((m) => m.job('b'));
    const c = p.run((m) => m.job('c'));
    const d = p.run((m) => m.job('d'));
    expect(made.map((m) => m.index)).toEqual([0, 1]);
    expect(p.load).toEqual([1, 1]);
    expect(p.waiting).toBe(2);
    // Member 1 is free first: the oldest waiting job goes there, not behind member 0's job.
    made[1]!.finish();
    expect(await b).toBe('b@1');
    expect(made[1]!.pending.map((j) => j.value)).toEqual(['c']);
    expect(p.waiting).toBe(1);
    made[1]!.finish();
    expect(await c).toBe('c@1');
    expect(made[1]!.pending.map((j) => j.value)).toEqual(['d']);
    made[0]!.finish();
    made[1]!.finish();
    expect(await Promise.all([a, d])).toEqual(['a@0', 'd@1']);
    expect(p.load).toEqual([0, 0]);
    expect(p.started).toBe(2);
    p.dispose();
    expect(made.every((m) => m.disposed)).toBe(true);
    await expect(p.run((m) => m.job())).rejects.toThrow('disposed');
  });

  it('frees the member of a job that throws or rejects (a crashed worker)', async () => {
    const { pool: p, made } = pool(1);
    await expect(
      p.run(() => {
        throw new Error('bad');
      }),
    ).rejects.toThrow('bad');
    const crashed = p.run((m) => m.job('x'));
    const next = p.run((m) => m.job('y'));
    made[0]!.finish(false);
    await expect(crashed).rejects.toThrow('crashed');
    made[0]!.finish();
    expect(await next).toBe('y@0');
    expect(p.load).toEqual([0]);
    expect(() => new WorkerPool((i) => new Member(i), 0)).toThrow('pool size');
  });

  it('a waiting job is cancelled by its signal; a running one is not', async () => {
    const { pool: p, made } = pool(1);
    const running = new AbortController();
    const a = p.run((m) => m.job('a'), { signal: running.signal });
    const waiting = new AbortController();
    const b = p.run((m) => m.job('b'), { signal: waiting.signal });
    const c = p.run((m) => m.job('c'));
    waiting.abort('forest closed');
    running.abort();
    await expect(b).rejects.toThrow('forest closed');
    expect(p.waiting).toBe(1);
    made[0]!.finish();
    expect(await a).toBe('a@0');
    made[0]!.finish();
    expect(await c).toBe('c@0');
    await expect(p.run((m) => m.job(), { signal: waiting.signal })).rejects.toThrow(
      'forest closed',
    );
  });

  it('dispose rejects the waiting jobs', async () => {
    const { pool: p } = pool(1);
    void p.run((m) => m.job('a')).catch(() => undefined);
    const b = p.run((m) => m.job('b'));
    p.dispose();
    await expect(b).rejects.toThrow('the worker pool was disposed');
  });
});

describe('LatestLane', () => {
  it('runs one job at a time; a newer job supersedes the one waiting, in the lane or in the pool', async () => {
    const { pool: p, made } = pool(1);
    const lane = new LatestLane(p);
    const a = lane.run((m) => m.job('a'));
    const b = lane.run((m) => m.job('b'));
    const c = lane.run((m) => m.job('c'));
    await expect(b).rejects.toThrow('superseded');
    expect(made[0]!.pending.map((j) => j.value)).toEqual(['a']);
    made[0]!.finish();
    expect(await a).toBe('a@0');
    expect(made[0]!.pending.map((j) => j.value)).toEqual(['c']);
    made[0]!.finish();
    expect(await c).toBe('c@0');

    // Behind another user's job, the lane's job waits in the pool's queue and is replaced there.
    const other = p.run((m) => m.job('export'));
    const d = lane.run((m) => m.job('d'));
    expect(p.waiting).toBe(1);
    const e = lane.run((m) => m.job('e'));
    await expect(d).rejects.toThrow('superseded');
    expect(p.waiting).toBe(1);
    made[0]!.finish();
    expect(await other).toBe('export@0');
    made[0]!.finish();
    expect(await e).toBe('e@0');
    lane.drop();
    await tick();
    expect(p.waiting).toBe(0);
  });

  it('a failed job frees the lane for the next one', async () => {
    const { pool: p, made } = pool(2);
    const lane = new LatestLane(p, 'replaced');
    const a = lane.run((m) => m.job('a'));
    const b = lane.run((m) => m.job('b'));
    const c = lane.run((m) => m.job('c'));
    await expect(b).rejects.toThrow('replaced');
    // One job of the lane at a time, even with a member free.
    expect(made).toHaveLength(1);
    made[0]!.finish(false);
    await expect(a).rejects.toThrow('crashed');
    expect(made[0]!.pending.map((j) => j.value)).toEqual(['c']);
    made[0]!.finish();
    expect(await c).toBe('c@0');
  });
});
