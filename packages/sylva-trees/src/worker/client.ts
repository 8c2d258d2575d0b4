/**
 * The base of every worker client (the generator's scheduler, the leaf inspector, the LOD and
 * export clients): a plain module with no Worker global, no React and no app state, so it is
 * unit-tested with a fake worker and can serve a library as it is.
 *
 * # What it does
 * - **Ready handshake**: requests wait until the worker has said `{ type: 'ready' }`.
 * - **One request in flight**; the waiting ones are either only the newest (`latest`: a newer
 *   request supersedes the one still waiting) or all of them in order (`queue`).
 * - **Crash**: a `{ type: 'fatal', message }` answer or the worker's `error` event terminates
 *   the worker and reports the request it held (never sent again: no resend loop); a worker
 *   that was ready is recreated, one that crashed while starting is not (it would crash again):
 *   what waited is dropped and the next request tries a fresh worker.
 * - **Time limit** (optional, for every request or per request): a request that runs too long
 *   stops the worker, which is recreated.
 * - **Dispose**: the worker is terminated and every request not answered is dropped (`dropped`,
 *   where promise-based clients reject).
 */

/** A started worker as a client sees it. */
export interface WorkerHandle<Req> {
  post(request: Req): void;
  terminate(): void;
}

/** How a worker is started. */
export interface WorkerStartOptions {
  /** Start a worker that accepts the debug messages (tests; `?debug=1` or a dev build). */
  debug?: boolean;
}

/** Starts a worker wired to the given callbacks (`onError` = the worker's `error` event). */
export type WorkerFactory<Req, Res> = (
  onMessage: (response: Res) => void,
  onError: (message: string) => void,
  options?: WorkerStartOptions,
) => WorkerHandle<Req>;

/** What every worker answers, besides its own messages: `ready` once, `fatal` when unusable. */
export interface WorkerMessage {
  type: string;
}

/** Why a request will never be answered. */
export type DropReason = 'superseded' | 'disposed' | 'cancelled' | 'failed-start';

/** What a client adds to the base: how its requests are sent and its answers delivered. */
export interface ClientHooks<Job, Req, Res> {
  /** The message that asks the worker for `job`. */
  message(job: Job): Req;
  /** Whether `response` answers `job`, the request in flight (it then leaves the worker). */
  ends(response: Res, job: Job): boolean;
  /** Every message but `ready` and `fatal`; `answered` is the job it ended, if any. */
  receive(response: Res, answered: Job | null): void;
  /** The worker is ready; `restarts` counts the workers recreated after a crash or time-out. */
  ready?(response: Res, restarts: number): void;
  /**
   * The worker crashed (`starting`: before it was ready); `lost` is the job it held. A ready
   * worker is recreated after this call.
   */
  crashed(message: string, lost: Job | null, starting: boolean): void;
  /**
   * The time limit of `job` (ms; undefined: none), read when it is sent; when absent, the
   * client's `timeLimitMs` applies to every job.
   */
  limitMs?(job: Job): number | undefined;
  /** `lost` ran longer than `limitMs`: the worker was stopped (and is recreated after this). */
  timedOut?(lost: Job, limitMs: number): void;
  /** A job that will never be sent or answered. */
  dropped?(job: Job, reason: DropReason): void;
  /** A job left the worker: answered, lost in a crash or a time-out, or cancelled. */
  finished?(job: Job): void;
  /** Whether a job is in flight or waiting. */
  busy?(busy: boolean): void;
}

/** Client settings. */
export interface ClientOptions {
  /** Start the worker at once (default) or with the first request. */
  eager?: boolean;
  /** `latest` (default): only the newest waiting request is kept; `queue`: all, in order. */
  policy?: 'latest' | 'queue';
  /** Longest one request may run in the worker (ms); no limit when absent. */
  timeLimitMs?: number;
  /** How the worker is started. */
  start?: WorkerStartOptions;
}

/** Owns one restartable worker; see the module docs. */
export class WorkerClient<Job, Req, Res extends WorkerMessage> {
  private worker: WorkerHandle<Req> | null = null;
  private ready = false;
  private current: Job | null = null;
  /** Sent before the waiting ones (debug hooks). */
  private first: Job | null = null;
  private readonly waiting: Job[] = [];
  private deadline: ReturnType<typeof setTimeout> | null = null;
  /** The limit the job in flight was sent with (the setting may change meanwhile). */
  private inFlightLimitMs = 0;
  private restartCount = 0;
  private isBusy = false;
  private isDisposed = false;
  private readonly eager: boolean;
  private readonly latest: boolean;
  private readonly startOptions: WorkerStartOptions | undefined;
  /** Longest one job may run (ms), read when a job is sent; undefined: no limit. */
  timeLimitMs: number | undefined;

  constructor(
    private readonly factory: WorkerFactory<Req, Res>,
    private readonly hooks: ClientHooks<Job, Req, Res>,
    options: ClientOptions = {},
  ) {
    this.eager = options.eager ?? true;
    this.latest = (options.policy ?? 'latest') === 'latest';
    this.timeLimitMs = options.timeLimitMs;
    this.startOptions = options.start;
    if (this.eager) this.start();
  }

  /** The job in flight, if any. */
  get inFlight(): Job | null {
    return this.current;
  }

  /** Whether the worker has said it is ready. */
  get isReady(): boolean {
    return this.ready;
  }

  /** Workers recreated after a crash or a time-out. */
  get restarts(): number {
    return this.restartCount;
  }

  /** Whether a job is in flight or waiting. */
  get busy(): boolean {
    return this.isBusy;
  }

  /** Whether [`dispose`] was called. */
  get disposed(): boolean {
    return this.isDisposed;
  }

  /** Whether any job waits to be sent. */
  get hasWaiting(): boolean {
    return this.first !== null || this.waiting.length > 0;
  }

  /** Queues `job` (see the policy) and sends it when the worker is free. */
  submit(job: Job): void {
    if (this.isDisposed) {
      this.hooks.dropped?.(job, 'disposed');
      return;
    }
    if (this.latest) this.drop('superseded');
    this.waiting.push(job);
    this.pump();
  }

  /** Sends `job` before any waiting one (replaces an earlier such job). */
  submitFirst(job: Job): void {
    if (this.isDisposed) return;
    if (this.first !== null) this.hooks.dropped?.(this.first, 'superseded');
    this.first = job;
    this.pump();
  }

  /** Starts the worker if there is none (a lazy client's first use). */
  ensureStarted(): void {
    if (this.worker === null && !this.isDisposed) this.start();
  }

  /** Drops the waiting jobs (not the one sent first). */
  dropWaiting(reason: DropReason): void {
    this.drop(reason);
    this.updateBusy();
  }

  private drop(reason: DropReason): void {
    for (const job of this.waiting.splice(0)) this.hooks.dropped?.(job, reason);
  }

  /**
   * Stops the job in flight: the worker is terminated and a fresh one started (a blocked wasm
   * call cannot be interrupted otherwise). Nothing is reported. Returns the stopped job.
   */
  stopInFlight(): Job | null {
    const lost = this.stopWorker();
    if (lost !== null) this.hooks.finished?.(lost);
    if (this.eager && !this.isDisposed) this.start();
    this.pump();
    return lost;
  }

  /** Terminates the worker; every job not answered is dropped. Unusable afterwards. */
  dispose(): void {
    this.isDisposed = true;
    const lost = this.stopWorker();
    if (lost !== null) this.hooks.dropped?.(lost, 'disposed');
    if (this.first !== null) this.hooks.dropped?.(this.first, 'disposed');
    this.first = null;
    this.dropWaiting('disposed');
  }

  private start(): void {
    this.ready = false;
    const handle: { current: WorkerHandle<Req> | null } = { current: null };
    const isCurrent = (): boolean => handle.current !== null && handle.current === this.worker;
    handle.current = this.factory(
      (response) => {
        if (isCurrent()) this.onMessage(response);
      },
      (message) => {
        if (isCurrent()) this.crash(message || 'the worker failed');
      },
      this.startOptions,
    );
    this.worker = handle.current;
  }

  private onMessage(response: Res): void {
    if (response.type === 'ready') {
      this.ready = true;
      this.hooks.ready?.(response, this.restartCount);
    } else if (response.type === 'fatal') {
      this.crash((response as { message?: string }).message ?? 'the worker failed');
      return;
    } else {
      const job = this.current;
      const answered = job !== null && this.hooks.ends(response, job) ? job : null;
      if (answered !== null) {
        this.clearDeadline();
        this.current = null;
        this.hooks.finished?.(answered);
      }
      this.hooks.receive(response, answered);
    }
    this.pump();
  }

  /** Terminates the worker and drops its job in flight (returned; never re-sent). */
  private stopWorker(): Job | null {
    this.clearDeadline();
    this.worker?.terminate();
    this.worker = null;
    this.ready = false;
    const lost = this.current;
    this.current = null;
    return lost;
  }

  private crash(message: string): void {
    const starting = !this.ready;
    const lost = this.stopWorker();
    if (lost !== null) this.hooks.finished?.(lost);
    if (starting) {
      // Restarting would loop: drop what waited; the next request tries a fresh worker.
      if (this.first !== null) this.hooks.dropped?.(this.first, 'failed-start');
      this.first = null;
      this.dropWaiting('failed-start');
      this.hooks.crashed(message, lost, true);
      this.updateBusy();
      return;
    }
    this.hooks.crashed(message, lost, false);
    this.restart();
  }

  private timedOut(): void {
    this.deadline = null;
    const limitMs = this.inFlightLimitMs;
    const lost = this.stopWorker();
    if (lost === null || this.isDisposed) return;
    this.hooks.finished?.(lost);
    this.hooks.timedOut?.(lost, limitMs);
    this.restart();
  }

  private restart(): void {
    this.restartCount++;
    if (this.eager && !this.isDisposed) this.start();
    this.pump();
  }

  private clearDeadline(): void {
    if (this.deadline !== null) clearTimeout(this.deadline);
    this.deadline = null;
  }

  private pump(): void {
    if (this.isDisposed) return;
    if (this.worker === null && this.hasWaiting) this.start();
    const worker = this.worker;
    if (worker !== null && this.ready && this.current === null) {
      const next = this.first ?? this.waiting.shift() ?? null;
      if (next === this.first) this.first = null;
      if (next !== null) {
        this.current = next;
        const limit = this.hooks.limitMs ? this.hooks.limitMs(next) : this.timeLimitMs;
        if (limit !== undefined) {
          this.inFlightLimitMs = limit;
          this.deadline = setTimeout(() => this.timedOut(), limit);
        }
        worker.post(this.hooks.message(next));
      }
    }
    this.updateBusy();
  }

  private updateBusy(): void {
    const busy = this.current !== null || this.hasWaiting;
    if (busy !== this.isBusy) {
      this.isBusy = busy;
      this.hooks.busy?.(busy);
    }
  }
}
