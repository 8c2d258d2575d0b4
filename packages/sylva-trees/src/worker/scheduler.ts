/**
 * Latest-request-wins scheduling over a restartable generator worker (no Worker globals here:
 * the worker comes from an injected factory, so this is unit-tested with a fake). A request
 * that runs past the time limit is stopped: the worker is terminated and recreated.
 *
 * Interactive requests (a slider being dragged) may be answered with a preview; when the drag
 * settles ([`GenerationScheduler.settle`], or [`SETTLE_MS`] without a new interactive request)
 * the same parameters are requested at full quality, so a preview never stays on screen.
 */
import type { Edit } from '../core/edits';
import type { Params, SylvaError, VolumePrimitive } from '../core/types';
import { WorkerClient, type WorkerFactory } from './client';
import type { DebugRequest, DebugResponse } from './debug';
import type {
  GenerateRequest,
  ReadyInfo,
  ReadyResponse,
  ResultResponse,
  WorkerRequest,
  WorkerResponse,
} from './protocol';

/** What the scheduler sends: the production requests, and the debug ones of a debug worker. */
export type SchedulerRequest = WorkerRequest | DebugRequest;
/** What the scheduler's worker answers. */
export type SchedulerResponse = WorkerResponse | DebugResponse;

/** Starts a generator worker for the scheduler. */
export type GeneratorFactory = WorkerFactory<SchedulerRequest, SchedulerResponse>;

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

/** A request of the scheduler: a tree, or a debug hook's message. */
type Slot = GenerateRequest | DebugRequest;

/** A drag has settled after this long without an interactive request (ms). */
export const SETTLE_MS = 150;

/** How a request is made. */
export interface RequestOptions {
  /** Part of a continuous edit (a slider drag): a preview answer is acceptable. */
  interactive?: boolean;
  /**
   * The hand edit list: part of the request's identity like the params (an edit reruns the
   * skeleton stage in the worker's session); sent only when non-empty.
   */
  edits?: readonly Edit[];
  /** Ask for the end grain of the tree's bark type ahead of a first cut ([`GenerateRequest`]). */
  endGrain?: boolean;
}

/** Default longest run of one request before the worker is stopped and recreated (ms). */
export const DEFAULT_TIME_LIMIT_MS = 10_000;

/** Scheduler settings. */
export interface SchedulerOptions {
  /** Longest a request may run in the worker before it is stopped (ms); default 10 s. */
  timeLimitMs?: number;
  /** Start a debug worker: [`debugPanic`] and [`debugHang`] work (tests, `?debug=1`). */
  debug?: boolean;
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

/**
 * Owns the worker (through [`WorkerClient`]): one request in flight, one pending slot that newer
 * requests overwrite, a debug request sent before it.
 */
export class GenerationScheduler {
  private readonly client: WorkerClient<Slot, SchedulerRequest, SchedulerResponse>;
  private readonly debug: boolean;
  private nextId = 1;
  /** The last interactive request's input, until the full tree for it is requested. */
  private unsettled: {
    params: Params;
    volumes?: VolumePrimitive[];
    edits?: readonly Edit[];
  } | null = null;
  private settleTimer: ReturnType<typeof setTimeout> | null = null;
  /**
   * Whether a drag settles by itself after [`SETTLE_MS`] without input (true), or only on
   * [`settle`] (benchmarks on software WebGL, whose frames take longer than the pause).
   */
  settleWhenIdle = true;
  /** Id of the last result delivered (a hash is only delivered for it). */
  private lastResultId = 0;

  constructor(
    factory: GeneratorFactory,
    private readonly callbacks: SchedulerCallbacks,
    options: SchedulerOptions = {},
  ) {
    this.debug = options.debug === true;
    const limit = checkLimit(options.timeLimitMs ?? DEFAULT_TIME_LIMIT_MS);
    this.client = new WorkerClient<Slot, SchedulerRequest, SchedulerResponse>(
      factory,
      {
        message: (slot) => slot,
        ends: (response, slot) => endsSlot(response, slot),
        receive: (response, answered) => this.receive(response, answered),
        ready: (response, restarts) => {
          const { registry, presets, version, exportFormats, threads } = response as ReadyResponse;
          // The export formats: an app's export workers run the same core (web: the pool).
          const info = {
            registry,
            presets,
            version,
            threads: threads ?? 1,
            ...(exportFormats ? { exportFormats } : {}),
          };
          this.callbacks.onReady(info, restarts);
        },
        crashed: (message, _lost, starting) =>
          this.callbacks.onError(
            starting
              ? { kind: 'internal', message: `The generator could not start: ${message}` }
              : { kind: 'panic', message },
            null,
          ),
        timedOut: (slot, limitMs) =>
          this.callbacks.onError(
            {
              kind: 'timeout',
              message: timeoutMessage(limitMs, slot.type === 'generate' ? slot.params : undefined),
            },
            slot.type === 'generate' ? slot.id : null,
          ),
        finished: (slot) => {
          if (slot.type === 'generate') this.callbacks.onProgress?.(null, null);
        },
        busy: (busy) => this.callbacks.onBusyChange(busy),
      },
      { timeLimitMs: limit, ...(this.debug ? { start: { debug: true } } : {}) },
    );
  }

  /** The time limit of one request (ms); a new value applies to the next request sent. */
  get timeLimitMs(): number {
    return this.client.timeLimitMs ?? DEFAULT_TIME_LIMIT_MS;
  }

  set timeLimitMs(ms: number) {
    this.client.timeLimitMs = checkLimit(ms);
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
      this.unsettled = {
        params,
        ...(volumes?.length ? { volumes } : {}),
        ...(options.edits?.length ? { edits: options.edits } : {}),
      };
      if (this.settleWhenIdle) this.settleTimer = setTimeout(() => this.settle(), SETTLE_MS);
    } else {
      this.unsettled = null;
    }
    this.client.submit({
      type: 'generate',
      id,
      params,
      ...(volumes?.length ? { volumes } : {}),
      ...(options.edits?.length ? { edits: [...options.edits] } : {}),
      ...(interactive ? { preview: true } : {}),
      ...(options.endGrain ? { endGrain: true } : {}),
    });
    return id;
  }

  /**
   * The continuous edit ended (slider released): requests the full tree for the last
   * interactive request, if any. Returns its id, or null when nothing was unsettled.
   */
  settle(): number | null {
    this.clearSettleTimer();
    const last = this.unsettled;
    if (last === null || this.client.disposed) return null;
    return this.request(last.params, last.volumes, last.edits ? { edits: last.edits } : {});
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
    if (this.client.disposed) return false;
    const generating = this.client.inFlight?.type === 'generate';
    const pending = this.client.hasWaiting;
    if (!generating && !pending) return false;
    this.client.dropWaiting('cancelled');
    if (generating) this.client.stopInFlight();
    return true;
  }

  /** Makes the worker panic on purpose once it is idle (debug workers only). */
  debugPanic(): void {
    this.client.submitFirst(this.debugSlot({ type: 'debug-panic' }));
  }

  /** Makes the worker busy-loop for `ms` once it is idle (debug workers: the time limit). */
  debugHang(ms: number): void {
    this.client.submitFirst(this.debugSlot({ type: 'debug-hang', ms }));
  }

  private debugSlot(request: DebugRequest): DebugRequest {
    if (!this.debug) throw new Error('debug requests need a scheduler made with debug: true');
    return request;
  }

  /** Number of times the worker was recreated after a crash. */
  get restartCount(): number {
    return this.client.restarts;
  }

  /** Terminates the worker; the scheduler is unusable afterwards. */
  dispose(): void {
    this.clearSettleTimer();
    this.unsettled = null;
    this.client.dispose();
  }

  private receive(response: SchedulerResponse, answered: Slot | null): void {
    switch (response.type) {
      case 'result':
        if (answered === null) return;
        this.lastResultId = response.id;
        this.callbacks.onResult(response);
        return;
      case 'hash':
        if (response.id === this.lastResultId) this.callbacks.onHash?.(response.hash, response.id);
        return;
      case 'error':
        if (answered !== null) this.callbacks.onError(response.error, response.id);
        return;
      case 'progress': {
        const slot = this.client.inFlight;
        if (slot?.type === 'generate' && slot.id === response.id) {
          this.callbacks.onProgress?.(response.fraction, response.id);
        }
        return;
      }
      default:
        return;
    }
  }
}

/** Whether `response` answers `slot`, the request in flight. */
function endsSlot(response: SchedulerResponse, slot: Slot): boolean {
  switch (response.type) {
    case 'result':
    case 'error':
      return slot.type === 'generate' && slot.id === response.id;
    case 'idle':
      return slot.type === 'debug-hang';
    default:
      return false;
  }
}
