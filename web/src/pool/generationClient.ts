/**
 * A member of the studio's generation pool (`generationPool.ts`): one generator worker (the same
 * worker script as the editor's, started with the first job) that serves the pool's independent
 * jobs, the levels of detail of a tree (`lods`) and mesh exports (`export`), one at a time. A
 * crashed worker rejects the job it held with a message saying so and is recreated for the next
 * job; an export still running after `EXPORT_TIME_LIMIT_MS` is stopped (all of it in
 * [`WorkerClient`]).
 */
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';
import {
  type DropReason,
  EXPORT_CANCELLED,
  EXPORT_TIME_LIMIT_MS,
  ExportError,
  exporterCrashed,
  type ExportFormat,
  type ExportOptions,
  exportRequest,
  type ExportResponse,
  exportTimedOut,
  type GeneratorWorkerFactory,
  type LodBuffers,
  type PoolMember,
  WorkerClient,
  type WorkerRequest,
  type WorkerResponse,
} from 'sylva-trees/worker';

/** A job of the worker: its message and how its answer or failure is delivered. */
interface Job {
  request: WorkerRequest;
  resolve(response: WorkerResponse): void;
  reject(error: Error): void;
}

/** Why a levels-of-detail job was never answered. */
const LODS_DROPPED: Record<DropReason, string> = {
  superseded: 'superseded',
  disposed: 'the generation worker was disposed',
  cancelled: 'the LOD request was cancelled',
  'failed-start': 'the generation worker could not start',
};

const isExport = (job: Job): boolean => job.request.type === 'export';

/** The message of a job lost when its worker crashed. */
function crashError(job: Job, message: string): Error {
  return isExport(job)
    ? exporterCrashed(message)
    : new Error(`the generation worker crashed: ${message}`);
}

/** See the module docs. */
export class GenerationClient implements PoolMember {
  private readonly client: WorkerClient<Job, WorkerRequest, WorkerResponse>;
  private nextId = 1;

  constructor(factory: GeneratorWorkerFactory) {
    this.client = new WorkerClient<Job, WorkerRequest, WorkerResponse>(
      factory,
      {
        message: (job) => job.request,
        ends: (response, job) =>
          (response.type === 'lods' || response.type === 'exported' || response.type === 'error') &&
          response.id === job.request.id,
        receive: (response, answered) => {
          if (answered === null) return;
          if (response.type !== 'error') answered.resolve(response);
          else if (isExport(answered)) {
            answered.reject(new ExportError(response.error.message, response.error));
          } else answered.reject(new Error(response.error.message));
        },
        crashed: (message, lost) => lost?.reject(crashError(lost, message)),
        limitMs: (job) => (isExport(job) ? EXPORT_TIME_LIMIT_MS : undefined),
        timedOut: (lost) => lost.reject(exportTimedOut()),
        dropped: (job, reason) =>
          job.reject(
            isExport(job)
              ? reason === 'failed-start'
                ? exporterCrashed('the worker could not start')
                : new ExportError(EXPORT_CANCELLED)
              : new Error(LODS_DROPPED[reason]),
          ),
      },
      { eager: false, policy: 'queue' },
    );
  }

  /** Workers recreated after a crash or a time-out. */
  get restarts(): number {
    return this.client.restarts;
  }

  /**
   * Generates the tree of `params` (with its volumes and hand edits) and its levels of detail;
   * `bakeLeaves`: every level also comes with its leaves baked into one mesh (the forest).
   */
  lods(
    params: Params,
    volumes?: VolumePrimitive[],
    edits?: readonly Edit[],
    bakeLeaves = false,
  ): Promise<LodBuffers> {
    const request: WorkerRequest = {
      type: 'lods',
      id: this.nextId++,
      params,
      ...(volumes?.length ? { volumes } : {}),
      ...(edits?.length ? { edits: [...edits] } : {}),
      ...(bakeLeaves ? { bakeLeaves } : {}),
    };
    return this.send(request).then((response) => (response as { lods: LodBuffers }).lods);
  }

  /** Regenerates `params` and exports it (the request `ExportClient` would send). */
  export(
    params: Params,
    volumes: VolumePrimitive[],
    format: ExportFormat,
    options: ExportOptions = {},
  ): Promise<ExportResponse> {
    const request = exportRequest(this.nextId++, params, volumes, format, options);
    return this.send(request) as Promise<ExportResponse>;
  }

  private send(request: WorkerRequest): Promise<WorkerResponse> {
    return new Promise<WorkerResponse>((resolve, reject) => {
      this.client.submit({ request, resolve, reject });
    });
  }

  /** Terminates the worker; pending jobs reject. */
  dispose(): void {
    this.client.dispose();
  }
}
