/**
 * Latest-request-wins scheduling over a restartable generator worker (no Worker globals here:
 * the worker comes from an injected factory, so this is unit-tested with a fake). A request
 * that runs past the time limit is stopped: the worker is terminated and recreated.
 *
 * Interactive requests (a slider being dragged) may be answered with a preview; when the drag
 * settles ([`GenerationScheduler.settle`], or [`SETTLE_MS`] without a new interactive request)
 * the same parameters are requested at full quality, so a preview never stays on screen.
 */
import type { Params, SylvaError, VolumePrimitive } from '../core/types';
import type { ReadyInfo, ResultResponse, WorkerRequest, WorkerResponse } from './protocol';

/** A started worker as the scheduler sees it. */
export interface WorkerHandle {
  post(request: WorkerRequest): void;
  terminate(): void;
}

/** Starts a worker wired to the given callbacks (`onError` = the worker's `error` event). */
export type WorkerFactory = (
  onMessage: (response: WorkerResponse) => void,
  onError: (message: string) => void,
) => WorkerHandle;

/** Notifications from the scheduler to the app. */
export interface SchedulerCallbacks {
  /** The (re)started worker is ready; `restarts` counts recreations so far. */
  onReady(info: ReadyInfo, restarts: number): void;
  /** A tree for request `result.id` (only the arrays that changed since the previous one). */
  onResult(result: ResultResponse): void;
  /** The content hash of the last result (`id`), computed after it. */
  onHash?(hash: string, id: number): void;
  /** A typed error for a request, or a crash (`kind: 'panic'`, `id` null). */
  onError(error: SylvaError, id: number | null): void;
  /** Whether a request is in flight or pending. */
  onBusyChange(busy: boolean): void;
  /** Growth progress (0..1) of the in-flight request `id`; null when nothing is in flight. */
  onProgress?(fraction: number | null, id: number | null): void;
}

type Slot =
  | { type: 'generate'; id: number; params: Params; volumes?: VolumePrimitive[]; preview?: boolean }
  | { type: 'debug-panic' }
  | { type: 'debug-hang'; ms: number };

/** A drag has settled after this long without an interactive request (ms). */
export const SETTLE_MS = 150;

/** How a request is made. */
export interface RequestOptions {
  /** Part of a continuous edit (a slider drag): a preview answer is acceptable. */
  interactive?: boolean;
}

/** Default longest run of one request before the worker is stopped and recreated (ms). */
export const DEFAULT_TIME_LIMIT_MS = 10_000;

/** Scheduler settings. */
export interface SchedulerOptions {
  /** Longest a request may run in the worker before it is stopped (ms); default 10 s. */
  timeLimitMs?: number;
}

/**
 * The message shown when a generation ran past the time limit; the advice names the parameters
 * that make the tree (growth's for a grown tree, Weber & Penn's otherwise).
 */
export function timeoutMessage(limitMs: number, params: Params = {}): string {
  const seconds = Number((limitMs / 1000).toFixed(1));
  const smaller =
    params.growth_mode === 1
      ? 'fewer Markers, Extra Markers or Iterations, a longer Internode'
      : 'fewer Levels or Branches';
  return (
    `Generation took longer than ${seconds} s and was stopped (the previous tree is kept). ` +
    `Try a smaller tree (${smaller}, lower Mesh Quality).`
  );
}

function checkLimit(ms: number): number {
  if (!Number.isFinite(ms) || ms <= 0) throw new RangeError(`bad time limit ${ms}`);
  return ms;
}

/** Owns the worker: one request in flight, one pending slot that newer requests overwrite. */
export class GenerationScheduler {
  private worker: WorkerHandle | null = null;
  private ready = false;
  private inFlight: Slot | null = null;
  private pending: Slot | null = null;
  private debugQueued: Slot | null = null;
  private deadline: ReturnType<typeof setTimeout> | null = null;
  /** The limit the in-flight request was sent with (the setting may change meanwhile). */
  private inFlightLimitMs = 0;
  private limitMs: number;
  private nextId = 1;
  private restarts = 0;
  private busy = false;
  private disposed = false;
  /** The last interactive request's input, until the full tree for it is requested. */
  private unsettled: { params: Params; volumes?: VolumePrimitive[] } | null = null;
  private settleTimer: ReturnType<typeof setTimeout> | null = null;
  /**
   * Whether a drag settles by itself after [`SETTLE_MS`] without input (true), or only on
   * [`settle`] (benchmarks on software WebGL, whose frames take longer than the pause).
   */
  settleWhenIdle = true;
  /** Id of the last result delivered (a hash is only delivered for it). */
  private lastResultId = 0;

  constructor(
    private readonly factory: WorkerFactory,
    private readonly callbacks: SchedulerCallbacks,
    options: SchedulerOptions = {},
  ) {
    this.limitMs = checkLimit(options.timeLimitMs ?? DEFAULT_TIME_LIMIT_MS);
    this.start();
  }

  /** The time limit of one request (ms); a new value applies to the next request sent. */
  get timeLimitMs(): number {
    return this.limitMs;
  }

  set timeLimitMs(ms: number) {
    this.limitMs = checkLimit(ms);
  }

  /**
   * Requests a tree; returns the request id. Supersedes any request not yet sent. An
   * interactive request may be answered with a preview; the full tree follows on [`settle`].
   */
  request(params: Params, volumes?: VolumePrimitive[], options: RequestOptions = {}): number {
    const id = this.nextId++;
    const interactive = options.interactive === true;
    this.clearSettleTimer();
    if (interactive) {
      this.unsettled = volumes?.length ? { params, volumes } : { params };
      if (this.settleWhenIdle) this.settleTimer = setTimeout(() => this.settle(), SETTLE_MS);
    } else {
      this.unsettled = null;
    }
    this.pending = {
      type: 'generate',
      id,
      params,
      ...(volumes?.length ? { volumes } : {}),
      ...(interactive ? { preview: true } : {}),
    };
    this.pump();
    return id;
  }

  /**
   * The continuous edit ended (slider released): requests the full tree for the last
   * interactive request, if any. Returns its id, or null when nothing was unsettled.
   */
  settle(): number | null {
    this.clearSettleTimer();
    const last = this.unsettled;
    if (last === null || this.disposed) return null;
    return this.request(last.params, last.volumes);
  }

  private clearSettleTimer(): void {
    if (this.settleTimer !== null) clearTimeout(this.settleTimer);
    this.settleTimer = null;
  }

  /**
   * Cancels the generation in flight and any pending one: the worker is terminated and a fresh
   * one started (a blocked wasm call cannot be interrupted otherwise). No error is reported and
   * the last tree stays. Returns whether there was anything to cancel.
   */
  cancel(): boolean {
    if (this.disposed) return false;
    const had = this.inFlight?.type === 'generate' || this.pending !== null;
    if (!had) return false;
    this.pending = null;
    if (this.inFlight?.type === 'generate') {
      this.stopWorker();
      this.callbacks.onProgress?.(null, null);
      this.start();
    }
    this.updateBusy();
    return true;
  }

  /** Makes the worker panic on purpose once it is idle (debug hook). */
  debugPanic(): void {
    this.debugQueued = { type: 'debug-panic' };
    this.pump();
  }

  /** Makes the worker busy-loop for `ms` once it is idle (debug hook for the time limit). */
  debugHang(ms: number): void {
    this.debugQueued = { type: 'debug-hang', ms };
    this.pump();
  }

  /** Number of times the worker was recreated after a crash. */
  get restartCount(): number {
    return this.restarts;
  }

  /** Terminates the worker; the scheduler is unusable afterwards. */
  dispose(): void {
    this.disposed = true;
    this.clearDeadline();
    this.clearSettleTimer();
    this.unsettled = null;
    this.worker?.terminate();
    this.worker = null;
    this.inFlight = null;
    this.pending = null;
    this.debugQueued = null;
    this.updateBusy();
  }

  private start(): void {
    this.ready = false;
    const handle: { current: WorkerHandle | null } = { current: null };
    const isCurrent = (): boolean => handle.current !== null && handle.current === this.worker;
    handle.current = this.factory(
      (response) => {
        if (isCurrent()) this.onMessage(response);
      },
      (message) => {
        if (isCurrent()) this.crash(message || 'the generator worker failed');
      },
    );
    this.worker = handle.current;
  }

  private onMessage(response: WorkerResponse): void {
    switch (response.type) {
      case 'ready': {
        this.ready = true;
        const { registry, presets, version } = response;
        this.callbacks.onReady({ registry, presets, version }, this.restarts);
        break;
      }
      case 'result':
        if (this.inFlight?.type !== 'generate' || this.inFlight.id !== response.id) return;
        this.finishInFlight();
        this.lastResultId = response.id;
        this.callbacks.onResult(response);
        break;
      case 'hash':
        if (response.id === this.lastResultId) this.callbacks.onHash?.(response.hash, response.id);
        return;
      case 'error':
        if (this.inFlight?.type !== 'generate' || this.inFlight.id !== response.id) return;
        this.finishInFlight();
        this.callbacks.onError(response.error, response.id);
        break;
      case 'progress':
        if (this.inFlight?.type === 'generate' && this.inFlight.id === response.id) {
          this.callbacks.onProgress?.(response.fraction, response.id);
        }
        return;
      case 'idle':
        if (this.inFlight?.type !== 'debug-hang') return;
        this.finishInFlight();
        break;
      case 'fatal':
        this.crash(response.message);
        return;
    }
    this.pump();
  }

  private finishInFlight(): void {
    this.clearDeadline();
    if (this.inFlight?.type === 'generate') this.callbacks.onProgress?.(null, null);
    this.inFlight = null;
  }

  private clearDeadline(): void {
    if (this.deadline !== null) clearTimeout(this.deadline);
    this.deadline = null;
  }

  /** Terminates the worker and drops its in-flight request (never re-sent: no resend loop). */
  private stopWorker(): void {
    this.clearDeadline();
    this.worker?.terminate();
    this.worker = null;
    this.ready = false;
    this.inFlight = null;
  }

  /** Drops the crashed worker and its in-flight request, reports, and starts a fresh worker. */
  private crash(message: string): void {
    const wasReady = this.ready;
    this.stopWorker();
    if (!wasReady) {
      // Crashed while starting: restarting would loop, so stop here.
      this.pending = null;
      this.debugQueued = null;
      this.callbacks.onError(
        { kind: 'internal', message: `The generator could not start: ${message}` },
        null,
      );
      this.updateBusy();
      return;
    }
    this.callbacks.onError({ kind: 'panic', message }, null);
    this.restart();
  }

  /** The in-flight request ran past the time limit: stop the worker, report, start a fresh one. */
  private timedOut(): void {
    this.deadline = null;
    const slot = this.inFlight;
    if (slot === null || this.disposed) return;
    this.stopWorker();
    this.callbacks.onError(
      {
        kind: 'timeout',
        message: timeoutMessage(
          this.inFlightLimitMs,
          slot.type === 'generate' ? slot.params : undefined,
        ),
      },
      slot.type === 'generate' ? slot.id : null,
    );
    this.restart();
  }

  private restart(): void {
    this.restarts++;
    if (!this.disposed) this.start();
    this.updateBusy();
  }

  private pump(): void {
    if (this.disposed) return;
    if (this.worker && this.ready && this.inFlight === null) {
      let next: Slot | null = null;
      if (this.debugQueued) {
        next = this.debugQueued;
        this.debugQueued = null;
      } else if (this.pending) {
        next = this.pending;
        this.pending = null;
      }
      if (next) {
        this.inFlight = next;
        this.inFlightLimitMs = this.limitMs;
        this.deadline = setTimeout(() => this.timedOut(), this.limitMs);
        this.worker.post(next);
      }
    }
    this.updateBusy();
  }

  private updateBusy(): void {
    const busy = this.inFlight !== null || this.pending !== null || this.debugQueued !== null;
    if (busy !== this.busy) {
      this.busy = busy;
      this.callbacks.onBusyChange(busy);
    }
  }
}
