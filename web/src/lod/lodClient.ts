/**
 * A second generator worker for levels of detail (the LOD panel and the forest), so LOD work never
 * delays the editing worker. Same worker code; `lods` requests only. Latest-wins per client: a
 * `request` made while one is in flight replaces any request still waiting (its promise rejects
 * with `superseded`); a crashed worker rejects what it held and is restarted on the next request
 * (all of it in [`WorkerClient`]; the worker starts with the first request).
 */
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';
import {
  type DropReason,
  type GeneratorWorkerFactory,
  type LodBuffers,
  WorkerClient,
  type WorkerRequest,
  type WorkerResponse,
} from 'sylva-trees/worker';

/** Rejection reason of a request replaced by a newer one. */
export const SUPERSEDED = 'superseded';

interface Waiting {
  id: number;
  params: Params;
  volumes: VolumePrimitive[] | undefined;
  edits: readonly Edit[] | undefined;
  resolve: (lods: LodBuffers) => void;
  reject: (reason: Error) => void;
}

const DROPPED: Record<DropReason, string> = {
  superseded: SUPERSEDED,
  disposed: 'the LOD worker was disposed',
  cancelled: 'the LOD request was cancelled',
  'failed-start': 'the LOD worker could not start',
};

/** See the module docs. */
export class LodClient {
  private readonly client: WorkerClient<Waiting, WorkerRequest, WorkerResponse>;
  private nextId = 1;

  /**
   * `latestWins`: false queues every request (the forest asks for several trees in turn).
   * `bakeLeaves`: every level also comes with its leaves baked into one mesh, in the worker.
   */
  constructor(factory: GeneratorWorkerFactory, latestWins = true, bakeLeaves = false) {
    this.client = new WorkerClient<Waiting, WorkerRequest, WorkerResponse>(
      factory,
      {
        message: ({ id, params, volumes, edits }) => ({
          type: 'lods',
          id,
          params,
          ...(volumes?.length ? { volumes } : {}),
          ...(edits?.length ? { edits: [...edits] } : {}),
          ...(bakeLeaves ? { bakeLeaves } : {}),
        }),
        ends: (response, job) =>
          (response.type === 'lods' || response.type === 'error') && response.id === job.id,
        receive: (response, answered) => {
          if (answered === null) return;
          if (response.type === 'lods') answered.resolve(response.lods);
          else if (response.type === 'error') answered.reject(new Error(response.error.message));
        },
        crashed: (message, lost) => lost?.reject(new Error(message)),
        dropped: (job, reason) => job.reject(new Error(DROPPED[reason])),
      },
      { eager: false, policy: latestWins ? 'latest' : 'queue' },
    );
  }

  /** Generates the tree of `params` (with its volumes and hand edits) and its levels of detail. */
  request(
    params: Params,
    volumes?: VolumePrimitive[],
    edits?: readonly Edit[],
  ): Promise<LodBuffers> {
    return new Promise<LodBuffers>((resolve, reject) => {
      this.client.submit({ id: this.nextId++, params, volumes, edits, resolve, reject });
    });
  }

  /** Terminates the worker; pending requests reject. */
  dispose(): void {
    this.client.dispose();
  }
}
