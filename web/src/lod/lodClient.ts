/**
 * The LOD panel's requests for levels of detail, run in the studio's generation pool
 * (`pool/generationPool.ts`), so LOD work never delays the editing worker. Latest-wins: one
 * request of the panel runs at a time, and a request made meanwhile replaces the one still
 * waiting (in the panel or in the pool's queue), whose promise rejects with `superseded`. A
 * crashed worker rejects the request it held and is restarted for the next job.
 */
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';
import { LatestLane, type LodBuffers } from 'sylva-trees/worker';
import type { GenerationClient } from '../pool/generationClient';
import type { GenerationPool } from '../pool/generationPool';

/** Rejection reason of a request replaced by a newer one. */
export const SUPERSEDED = 'superseded';

/** See the module docs. */
export class LodClient {
  private readonly lane: LatestLane<GenerationClient>;

  constructor(pool: GenerationPool) {
    this.lane = new LatestLane(pool.workers, SUPERSEDED);
  }

  /** Generates the tree of `params` (with its volumes and hand edits) and its levels of detail. */
  request(
    params: Params,
    volumes?: VolumePrimitive[],
    edits?: readonly Edit[],
  ): Promise<LodBuffers> {
    return this.lane.run((worker) => worker.lods(params, volumes, edits));
  }

  /** Drops the waiting request (it rejects); the running one settles in its worker. */
  dispose(): void {
    this.lane.drop(new Error('the LOD request was cancelled'));
  }
}
