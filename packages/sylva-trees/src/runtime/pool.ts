/**
 * A pool of generation workers for independent jobs (the forest's trees, level-of-detail bakes,
 * exports), apart from the editor's own worker so editing stays responsive while the pool works.
 * Each member is a client of one worker (made the first time a job is given to it). Jobs wait in
 * one queue, in order, and each starts on a free member (no job running; the lowest index first),
 * so `size` jobs run side by side and a long job (a large export) never holds others back while
 * another member is idle. A waiting job can be cancelled (`signal`); a running one settles as
 * its member says (a crashed worker rejects it, and its client recreates the worker).
 * [`LatestLane`] runs a pool's jobs latest-wins (the LOD panel: a newer request supersedes the
 * one still waiting).
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

/** How one job is run. */
export interface PoolRunOptions {
  /** Aborting it while the job waits removes the job (it rejects with the abort reason). */
  signal?: AbortSignal;
}

/** Default rejection message of a cancelled job. */
export const POOL_JOB_CANCELLED = 'the pool job was cancelled';

interface Waiting<M> {
  start(member: M, index: number): void;
  reject(error: Error): void;
}

/** The abort reason as an Error (a string becomes its message). */
function abortError(signal: AbortSignal): Error {
  const reason: unknown = signal.reason;
  // `abort()` without a reason gives a DOMException named AbortError: the default message.
  if (reason instanceof Error && reason.name !== 'AbortError') return reason;
  return new Error(typeof reason === 'string' ? reason : POOL_JOB_CANCELLED);
}

/** See the module docs. */
export class WorkerPool<M extends PoolMember> {
  private readonly members: (M | null)[];
  private readonly busy: boolean[];
  private readonly queue: Waiting<M>[] = [];
  private disposed = false;

  /** `create(i)` makes member `i` the first time a job is given to it. */
  constructor(
    private readonly create: (index: number) => M,
    readonly size: number,
  ) {
    if (!Number.isInteger(size) || size < 1) throw new Error(`pool size ${size} is not 1 or more`);
    this.members = new Array<M | null>(size).fill(null);
    this.busy = new Array<boolean>(size).fill(false);
  }

  /** Jobs running, per member (0 or 1). */
  get load(): readonly number[] {
    return this.busy.map((b) => (b ? 1 : 0));
  }

  /** Jobs waiting for a free member. */
  get waiting(): number {
    return this.queue.length;
  }

  /** Members made so far (each has started its worker). */
  get started(): number {
    return this.members.filter((m) => m !== null).length;
  }

  /**
   * Runs `job` on the first free member, after the jobs given before it; settles as the job
   * does. `options.signal` cancels it while it waits.
   */
  run<T>(job: (member: M) => Promise<T>, options: PoolRunOptions = {}): Promise<T> {
    if (this.disposed) return Promise.reject(new Error('the worker pool was disposed'));
    const { signal } = options;
    if (signal?.aborted) return Promise.reject(abortError(signal));
    return new Promise<T>((resolve, reject) => {
      const onAbort = () => {
        const at = this.queue.indexOf(entry);
        if (at < 0) return;
        this.queue.splice(at, 1);
        reject(abortError(signal!));
      };
      const entry: Waiting<M> = {
        start: (member, index) => {
          signal?.removeEventListener('abort', onAbort);
          let promise: Promise<T>;
          try {
            promise = job(member);
          } catch (e) {
            promise = Promise.reject(e instanceof Error ? e : new Error(String(e)));
          }
          promise
            .finally(() => {
              this.busy[index] = false;
              this.pump();
            })
            .then(resolve, reject);
        },
        reject: (error) => {
          signal?.removeEventListener('abort', onAbort);
          reject(error);
        },
      };
      signal?.addEventListener('abort', onAbort, { once: true });
      this.queue.push(entry);
      this.pump();
    });
  }

  /** Starts waiting jobs on free members. */
  private pump(): void {
    while (!this.disposed && this.queue.length > 0) {
      const index = this.busy.indexOf(false);
      if (index < 0) return;
      const entry = this.queue.shift()!;
      const member = (this.members[index] ??= this.create(index));
      this.busy[index] = true;
      entry.start(member, index);
    }
  }

  /** Rejects the waiting jobs and disposes of every member made (its running job rejects as its dispose says). */
  dispose(): void {
    this.disposed = true;
    for (const entry of this.queue.splice(0))
      entry.reject(new Error('the worker pool was disposed'));
    for (const m of this.members) m?.dispose();
    this.members.fill(null);
  }
}

/** A job of a [`LatestLane`] not yet started. */
interface LaneJob<M> {
  run: (member: M) => Promise<unknown>;
  resolve: (value: unknown) => void;
  reject: (error: Error) => void;
  /** Set once the job was given to the pool (where it may still wait). */
  queued: AbortController | null;
}

/**
 * Latest-wins use of a pool: at most one job of the lane runs at a time and at most one waits
 * (in the lane or in the pool's queue); a newer job replaces the waiting one, which rejects with
 * `supersededMessage`.
 */
export class LatestLane<M extends PoolMember> {
  private running = false;
  private next: LaneJob<M> | null = null;

  constructor(
    private readonly pool: WorkerPool<M>,
    private readonly supersededMessage = 'superseded',
  ) {}

  /** Runs `job` once the lane's running job is done, unless a newer job replaces it first. */
  run<T>(job: (member: M) => Promise<T>): Promise<T> {
    this.drop(new Error(this.supersededMessage));
    return new Promise<T>((resolve, reject) => {
      const settle = (value: unknown): void => resolve(value as T);
      this.next = { run: job, resolve: settle, reject, queued: null };
      this.pump();
    });
  }

  /** Drops the waiting job, if any (it rejects with `error`). */
  drop(error: Error = new Error(POOL_JOB_CANCELLED)): void {
    const next = this.next;
    this.next = null;
    if (next === null) return;
    if (next.queued) next.queued.abort(error);
    else next.reject(error);
  }

  private pump(): void {
    const next = this.next;
    if (next === null || this.running || next.queued) return;
    const controller = new AbortController();
    next.queued = controller;
    let started = false;
    this.pool
      .run(
        (member) => {
          started = true;
          this.running = true;
          if (this.next === next) this.next = null;
          return next.run(member);
        },
        { signal: controller.signal },
      )
      .finally(() => {
        if (!started) return;
        this.running = false;
        this.pump();
      })
      .then(next.resolve, next.reject);
  }
}
