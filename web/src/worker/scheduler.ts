/**
 * Latest-request-wins scheduling over a restartable generator worker (no Worker globals here:
 * the worker comes from an injected factory, so this is unit-tested with a fake).
 */
import type { Params, SylvaError } from '../core/types';
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
  /** A tree for request `result.id`. */
  onResult(result: ResultResponse): void;
  /** A typed error for a request, or a crash (`kind: 'panic'`, `id` null). */
  onError(error: SylvaError, id: number | null): void;
  /** Whether a request is in flight or pending. */
  onBusyChange(busy: boolean): void;
}

type Slot = { type: 'generate'; id: number; params: Params } | { type: 'debug-panic' };

/** Owns the worker: one request in flight, one pending slot that newer requests overwrite. */
export class GenerationScheduler {
  private worker: WorkerHandle | null = null;
  private ready = false;
  private inFlight: Slot | null = null;
  private pending: Slot | null = null;
  private panicQueued = false;
  private nextId = 1;
  private restarts = 0;
  private busy = false;
  private disposed = false;

  constructor(
    private readonly factory: WorkerFactory,
    private readonly callbacks: SchedulerCallbacks,
  ) {
    this.start();
  }

  /** Requests a tree; returns the request id. Supersedes any request not yet sent. */
  request(params: Params): number {
    const id = this.nextId++;
    this.pending = { type: 'generate', id, params };
    this.pump();
    return id;
  }

  /** Makes the worker panic on purpose once it is idle (debug hook). */
  debugPanic(): void {
    this.panicQueued = true;
    this.pump();
  }

  /** Number of times the worker was recreated after a crash. */
  get restartCount(): number {
    return this.restarts;
  }

  /** Terminates the worker; the scheduler is unusable afterwards. */
  dispose(): void {
    this.disposed = true;
    this.worker?.terminate();
    this.worker = null;
    this.inFlight = null;
    this.pending = null;
    this.panicQueued = false;
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
        this.inFlight = null;
        this.callbacks.onResult(response);
        break;
      case 'error':
        if (this.inFlight?.type !== 'generate' || this.inFlight.id !== response.id) return;
        this.inFlight = null;
        this.callbacks.onError(response.error, response.id);
        break;
      case 'fatal':
        this.crash(response.message);
        return;
    }
    this.pump();
  }

  /** Drops the crashed worker and its in-flight request, reports, and starts a fresh worker. */
  private crash(message: string): void {
    const wasReady = this.ready;
    this.worker?.terminate();
    this.worker = null;
    this.ready = false;
    this.inFlight = null;
    if (!wasReady) {
      // Crashed while starting: restarting would loop, so stop here.
      this.pending = null;
      this.panicQueued = false;
      this.callbacks.onError(
        { kind: 'internal', message: `The generator could not start: ${message}` },
        null,
      );
      this.updateBusy();
      return;
    }
    this.callbacks.onError({ kind: 'panic', message }, null);
    this.restarts++;
    if (!this.disposed) this.start();
    this.updateBusy();
  }

  private pump(): void {
    if (this.disposed) return;
    if (this.worker && this.ready && this.inFlight === null) {
      let next: Slot | null = null;
      if (this.panicQueued) {
        this.panicQueued = false;
        next = { type: 'debug-panic' };
      } else if (this.pending) {
        next = this.pending;
        this.pending = null;
      }
      if (next) {
        this.inFlight = next;
        this.worker.post(next);
      }
    }
    this.updateBusy();
  }

  private updateBusy(): void {
    const busy = this.inFlight !== null || this.pending !== null || this.panicQueued;
    if (busy !== this.busy) {
      this.busy = busy;
      this.callbacks.onBusyChange(busy);
    }
  }
}
