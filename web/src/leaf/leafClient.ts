/**
 * Latest-request-wins client for the leaf inspector: its own generator worker (so editing a
 * leaf never waits behind a tree), one request in flight, one pending slot that newer requests
 * overwrite; a crashed worker is recreated and the pending request sent to the new one.
 */
import type { LeafInspection, Params, Preset, SylvaError } from '../core/types';
import type { LeafRequest } from '../worker/protocol';
import type { WorkerFactory, WorkerHandle } from '../worker/scheduler';

/** What the inspector asks for. */
export type LeafQuery = Omit<LeafRequest, 'type' | 'id'>;

/** Callbacks of the leaf client. */
export interface LeafCallbacks {
  onLeaf(leaf: LeafInspection, id: number): void;
  onError(error: SylvaError): void;
  /** The worker is ready; carries the leaf presets. */
  onPresets?(presets: Preset[]): void;
}

/** Owns the inspector's worker. */
export class LeafClient {
  private worker: WorkerHandle | null = null;
  private ready = false;
  private inFlight: number | null = null;
  private pending: LeafRequest | null = null;
  private nextId = 1;
  private disposed = false;

  constructor(
    private readonly factory: WorkerFactory,
    private readonly callbacks: LeafCallbacks,
  ) {
    this.start();
  }

  /** Requests a leaf drawing; supersedes any request not yet sent. Returns its id. */
  request(params: Params, step: number, triangulation: boolean): number {
    const id = this.nextId++;
    this.pending = { type: 'leaf', id, params, step, triangulation };
    this.pump();
    return id;
  }

  /** Terminates the worker. */
  dispose(): void {
    this.disposed = true;
    this.worker?.terminate();
    this.worker = null;
  }

  private start(): void {
    this.ready = false;
    this.inFlight = null;
    const worker = this.factory(
      (response) => {
        if (worker !== this.worker) return;
        if (response.type === 'ready') {
          this.ready = true;
          this.callbacks.onPresets?.(response.leafPresets ?? []);
        } else if (response.type === 'leaf') {
          if (response.id !== this.inFlight) return;
          this.inFlight = null;
          const { svg, iterations, nodes, links, segments, auxins, triangles, hash, id } = response;
          const leaf = { svg, iterations, nodes, links, segments, auxins, triangles, hash };
          this.callbacks.onLeaf(leaf, id);
        } else if (response.type === 'error') {
          if (response.id !== this.inFlight) return;
          this.inFlight = null;
          this.callbacks.onError(response.error);
        } else if (response.type === 'fatal') {
          this.crash(response.message);
          return;
        }
        this.pump();
      },
      (message) => {
        if (worker === this.worker) this.crash(message);
      },
    );
    this.worker = worker;
  }

  private crash(message: string): void {
    this.worker?.terminate();
    this.worker = null;
    const wasReady = this.ready;
    this.callbacks.onError({ kind: 'panic', message });
    // A worker that crashed while starting would crash again: stop there.
    if (!this.disposed && wasReady) this.start();
  }

  private pump(): void {
    if (this.disposed || !this.worker || !this.ready || this.inFlight !== null) return;
    const next = this.pending;
    if (!next) return;
    this.pending = null;
    this.inFlight = next.id;
    this.worker.post(next);
  }
}
