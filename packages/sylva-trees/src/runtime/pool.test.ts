import { describe, expect, it } from 'vitest';
import { poolSize, WorkerPool } from './pool';

/** A member whose jobs settle when the test says. */
class Member {
  disposed = false;
  readonly pending: (() => void)[] = [];
  constructor(readonly index: number) {}
  job(): Promise<number> {
    return new Promise((resolve) => this.pending.push(() => resolve(this.index)));
  }
  dispose(): void {
    this.disposed = true;
  }
}

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
  it('spreads jobs over the least busy members, making each once', async () => {
    const made: Member[] = [];
    const pool = new WorkerPool((i) => {
      const m = new Member(i);
      made.push(m);
      return m;
    }, 2);
    const a = pool.run((m) => m.job());
    const b = pool.run((m) => m.job());
    const c = pool.run((m) => m.job());
    expect(made.map((m) => m.index)).toEqual([0, 1]);
    expect(pool.load).toEqual([2, 1]);
    made[1]!.pending.shift()!();
    expect(await b).toBe(1);
    expect(pool.load).toEqual([2, 0]);
    // The next job goes to the idle member.
    const d = pool.run((m) => m.job());
    expect(pool.load).toEqual([2, 1]);
    made[0]!.pending.splice(0).forEach((f) => f());
    made[1]!.pending.splice(0).forEach((f) => f());
    expect(await Promise.all([a, c, d])).toEqual([0, 0, 1]);
    expect(pool.load).toEqual([0, 0]);
    pool.dispose();
    expect(made.every((m) => m.disposed)).toBe(true);
    await expect(pool.run((m) => m.job())).rejects.toThrow('disposed');
  });

  it('frees the slot of a job that throws or rejects', async () => {
    const pool = new WorkerPool((i) => new Member(i), 1);
    await expect(
      pool.run(() => {
        throw new Error('bad');
      }),
    ).rejects.toThrow('bad');
    await expect(pool.run(() => Promise.reject(new Error('no')))).rejects.toThrow('no');
    expect(pool.load).toEqual([0]);
    expect(() => new WorkerPool((i) => new Member(i), 0)).toThrow('pool size');
  });
});
