/**
 * A pool of generation workers for independent jobs (the forest's trees, level-of-detail bakes,
 * exports), apart from the editor's own worker so editing stays responsive while the pool works.
 * Each member is a client of one worker (made on first use); a job goes to the member with the
 * fewest jobs in flight, the lowest index on a tie, so `size` jobs run side by side and the rest
 * queue in the members' own queues.
 */

/** A pool member: anything that owns a worker and can be disposed of. */
export interface PoolMember {
  dispose(): void;
}

/** Pool size for `cores` logical cores (`navigator.hardwareConcurrency`): 1..`max`. */
export function poolSize(cores: number | undefined, max = 4): number {
  const n = Number.isFinite(cores) ? Math.floor(cores!) : 1;
  return Math.max(1, Math.min(n, Math.max(1, Math.floor(max))));
}

/** See the module docs. */
export class WorkerPool<M extends PoolMember> {
  private readonly members: (M | null)[];
  private readonly busy: number[];
  private disposed = false;

  /** `create(i)` makes member `i` the first time a job is given to it. */
  constructor(
    private readonly create: (index: number) => M,
    readonly size: number,
  ) {
    if (!Number.isInteger(size) || size < 1) throw new Error(`pool size ${size} is not 1 or more`);
    this.members = new Array<M | null>(size).fill(null);
    this.busy = new Array<number>(size).fill(0);
  }

  /** Jobs given and not yet settled, per member. */
  get load(): readonly number[] {
    return [...this.busy];
  }

  /** Runs `job` on the least busy member; settles as the job does. */
  run<T>(job: (member: M) => Promise<T>): Promise<T> {
    if (this.disposed) return Promise.reject(new Error('the worker pool was disposed'));
    let best = 0;
    for (let i = 1; i < this.size; i++) if (this.busy[i]! < this.busy[best]!) best = i;
    const member = (this.members[best] ??= this.create(best));
    this.busy[best]!++;
    const done = () => {
      this.busy[best]!--;
    };
    let promise: Promise<T>;
    try {
      promise = job(member);
    } catch (e) {
      done();
      return Promise.reject(e instanceof Error ? e : new Error(String(e)));
    }
    return promise.finally(done);
  }

  /** Disposes of every member made (their pending jobs reject as each member's dispose says). */
  dispose(): void {
    this.disposed = true;
    for (const m of this.members) m?.dispose();
    this.members.fill(null);
  }
}
