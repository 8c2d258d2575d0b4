/**
 * Latest-request-wins client for the leaf inspector: its own generator worker (so editing a
 * leaf never waits behind a tree), one request in flight, one pending slot that newer requests
 * overwrite; a crashed worker is recreated and the pending request sent to the new one (all of
 * it in [`WorkerClient`]).
 */
import type { LeafInspection, LeafPreset, Params, SylvaError } from 'sylva-trees/core';
import {
  type GeneratorWorkerFactory,
  type LeafRequest,
  WorkerClient,
  type WorkerRequest,
  type WorkerResponse,
} from 'sylva-trees/worker';

/** What the inspector asks for. */
export type LeafQuery = Omit<LeafRequest, 'type' | 'id'>;

/** Callbacks of the leaf client. */
export interface LeafCallbacks {
  onLeaf(leaf: LeafInspection, id: number): void;
  onError(error: SylvaError): void;
  /** The worker is ready; carries the leaf presets. */
  onPresets?(presets: LeafPreset[]): void;
}

/** Owns the inspector's worker. */
export class LeafClient {
  private readonly client: WorkerClient<LeafRequest, WorkerRequest, WorkerResponse>;
  private nextId = 1;

  constructor(factory: GeneratorWorkerFactory, callbacks: LeafCallbacks) {
    this.client = new WorkerClient<LeafRequest, WorkerRequest, WorkerResponse>(factory, {
      message: (request) => request,
      ends: (response, request) =>
        (response.type === 'leaf' || response.type === 'error') && response.id === request.id,
      receive: (response, answered) => {
        if (answered === null) return;
        if (response.type === 'leaf') {
          const { svg, iterations, nodes, links, segments, auxins, triangles, hash, id } = response;
          const leaf = { svg, iterations, nodes, links, segments, auxins, triangles, hash };
          callbacks.onLeaf(leaf, id);
        } else if (response.type === 'error') {
          callbacks.onError(response.error);
        }
      },
      ready: (response) => {
        if (response.type === 'ready') callbacks.onPresets?.(response.leafPresets ?? []);
      },
      crashed: (message) => callbacks.onError({ kind: 'panic', message }),
    });
  }

  /** Requests a leaf drawing; supersedes any request not yet sent. Returns its id. */
  request(params: Params, step: number, triangulation: boolean): number {
    const id = this.nextId++;
    this.client.submit({ type: 'leaf', id, params, step, triangulation });
    return id;
  }

  /** Terminates the worker. */
  dispose(): void {
    this.client.dispose();
  }
}
