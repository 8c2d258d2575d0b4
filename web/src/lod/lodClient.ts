/**
 * A second generator worker for levels of detail (the LOD panel and the forest), so LOD work never
 * delays the editing worker. Same worker code; `lods` requests only. Latest-wins per client: a
 * `request` made while one is in flight replaces any request still waiting (its promise rejects
 * with `superseded`); a crashed worker rejects what it held and is restarted on the next request.
 */
import type { Params, VolumePrimitive } from '../core/types';
import type { WorkerFactory, WorkerHandle } from '../worker/scheduler';
import type { WorkerResponse } from '../worker/protocol';
import type { LodBuffers } from './types';

/** Rejection reason of a request replaced by a newer one. */
export const SUPERSEDED = 'superseded';

interface Waiting {
  id: number;
  params: Params;
  volumes: VolumePrimitive[] | undefined;
  resolve: (lods: LodBuffers) => void;
  reject: (reason: Error) => void;
}

/** See the module docs. */
export class LodClient {
  private worker: WorkerHandle | null = null;
  private inFlight: Waiting | null = null;
  private waiting: Waiting | null = null;
  private nextId = 1;
  private disposed = false;

  /** `latestWins`: false queues every request (the forest asks for several trees in turn). */
  constructor(
    private readonly factory: WorkerFactory,
    private readonly latestWins = true,
  ) {}

  private readonly queue: Waiting[] = [];

  /** Generates the tree of `params` with its levels of detail. */
  request(params: Params, volumes?: VolumePrimitive[]): Promise<LodBuffers> {
    return new Promise<LodBuffers>((resolve, reject) => {
      if (this.disposed) {
        reject(new Error('the LOD worker was disposed'));
        return;
      }
      const item: Waiting = { id: this.nextId++, params, volumes, resolve, reject };
      if (this.latestWins) {
        this.waiting?.reject(new Error(SUPERSEDED));
        this.waiting = item;
      } else {
        this.queue.push(item);
      }
      this.pump();
    });
  }

  /** Terminates the worker; pending requests reject. */
  dispose(): void {
    this.disposed = true;
    this.fail(new Error('the LOD worker was disposed'));
    this.worker?.terminate();
    this.worker = null;
  }

  private pump(): void {
    if (this.inFlight || this.disposed) return;
    const next = this.latestWins ? this.waiting : (this.queue.shift() ?? null);
    if (!next) return;
    if (this.latestWins) this.waiting = null;
    this.inFlight = next;
    this.worker ??= this.factory(
      (response) => this.onMessage(response),
      (message) => this.crash(message || 'the LOD worker failed'),
    );
    this.worker.post(
      next.volumes?.length
        ? { type: 'lods', id: next.id, params: next.params, volumes: next.volumes }
        : { type: 'lods', id: next.id, params: next.params },
    );
  }

  private onMessage(response: WorkerResponse): void {
    const current = this.inFlight;
    if (response.type === 'fatal') {
      this.crash(response.message);
      return;
    }
    if (!current) return;
    if (response.type === 'lods' && response.id === current.id) {
      this.inFlight = null;
      current.resolve(response.lods);
      this.pump();
    } else if (response.type === 'error' && response.id === current.id) {
      this.inFlight = null;
      current.reject(new Error(response.error.message));
      this.pump();
    }
  }

  private crash(message: string): void {
    this.worker?.terminate();
    this.worker = null;
    const current = this.inFlight;
    this.inFlight = null;
    current?.reject(new Error(message));
    this.pump();
  }

  private fail(error: Error): void {
    this.inFlight?.reject(error);
    this.inFlight = null;
    this.waiting?.reject(error);
    this.waiting = null;
    for (const q of this.queue.splice(0)) q.reject(error);
  }
}
