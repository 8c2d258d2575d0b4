/**
 * Main-thread client of the mesh export: a worker of its own (started on first use, so an
 * export never waits behind or cancels the interactive generation), which reports the formats
 * the core supports in its `ready` message.
 */
import type { Edit } from '../core/edits';
import type { Params, SylvaError, VolumePrimitive } from '../core/types';
import { WorkerClient } from '../worker/client';
import type { GeneratorWorkerFactory, WorkerRequest, WorkerResponse } from '../worker/protocol';
import type { ExportFormat, ExportRequest, ExportResponse, LeafExport } from './exportProtocol';

/** Longest an export may take (ms). */
export const EXPORT_TIME_LIMIT_MS = 60_000;

interface Pending {
  request: ExportRequest;
  resolve(response: ExportResponse): void;
  reject(error: Error): void;
}

/** An export failure with the core's error when there is one. */
export class ExportError extends Error {
  override name = 'ExportError';
  constructor(
    message: string,
    readonly sylva: SylvaError | null = null,
  ) {
    super(message);
  }
}

/** What an export is asked with besides the tree's params, volumes and format. */
export interface ExportOptions {
  leaves?: LeafExport;
  strict?: boolean;
  name?: string;
  edits?: readonly Edit[];
  /** `lods`: the impostor GLB to store in the ZIP with the levels. */
  impostor?: Uint8Array;
}

/**
 * The worker message of export `id` (every client of the export handler writes it here, so an
 * export carries the same inputs whichever worker runs it).
 */
export function exportRequest(
  id: number,
  params: Params,
  volumes: VolumePrimitive[],
  format: ExportFormat,
  options: ExportOptions = {},
): ExportRequest {
  return {
    type: 'export',
    id,
    params,
    format,
    ...(volumes.length > 0 ? { volumes } : {}),
    ...(options.edits?.length ? { edits: [...options.edits] } : {}),
    ...(options.leaves ? { leaves: options.leaves } : {}),
    ...(options.strict ? { strict: true } : {}),
    ...(options.name ? { name: options.name } : {}),
    ...(options.impostor ? { impostor: options.impostor } : {}),
  };
}

/** Message of an export dropped before it was answered. */
export const EXPORT_CANCELLED = 'The export was cancelled.';

/** The error of an export lost in a crash of its worker (`message`: the crash's). */
export function exporterCrashed(message: string): ExportError {
  return new ExportError(`The exporter crashed: ${message}`);
}

/** The error of an export stopped at [`EXPORT_TIME_LIMIT_MS`]. */
export function exportTimedOut(): ExportError {
  return new ExportError(`The export took longer than ${EXPORT_TIME_LIMIT_MS / 1000} s.`);
}

/** The error of an export in a format the core lacks. */
export function unsupportedFormat(format: ExportFormat): ExportError {
  return new ExportError(`This Sylva core cannot export ${format.toUpperCase()} yet.`);
}

/** Owns the export worker (through [`WorkerClient`]: exports run one after the other). */
export class ExportClient {
  private readonly client: WorkerClient<Pending, WorkerRequest, WorkerResponse>;
  private ready: Promise<ExportFormat[]> | null = null;
  private settleReady: {
    resolve(formats: ExportFormat[]): void;
    reject(error: Error): void;
  } | null = null;
  private nextId = 1;

  constructor(factory: GeneratorWorkerFactory) {
    this.client = new WorkerClient<Pending, WorkerRequest, WorkerResponse>(
      factory,
      {
        message: (job) => job.request,
        ends: (response, job) =>
          (response.type === 'exported' || response.type === 'error') &&
          response.id === job.request.id,
        receive: (response, answered) => {
          if (answered === null) return;
          if (response.type === 'exported') answered.resolve(response);
          else if (response.type === 'error') {
            answered.reject(new ExportError(response.error.message, response.error));
          }
        },
        ready: (response) => {
          if (response.type === 'ready') this.settleReady?.resolve(response.exportFormats ?? []);
          this.settleReady = null;
        },
        crashed: (message, lost, starting) => {
          const error = exporterCrashed(message);
          lost?.reject(error);
          // A worker that never started: the next call starts a fresh one.
          this.settleReady?.reject(error);
          this.settleReady = null;
          if (starting) this.ready = null;
        },
        timedOut: (lost) => lost.reject(exportTimedOut()),
        dropped: (job) => job.reject(new ExportError(EXPORT_CANCELLED)),
      },
      { eager: false, policy: 'queue', timeLimitMs: EXPORT_TIME_LIMIT_MS },
    );
  }

  /** The formats the core can export (starts the worker). */
  formats(): Promise<ExportFormat[]> {
    if (!this.ready) {
      this.ready = new Promise<ExportFormat[]>((resolve, reject) => {
        this.settleReady = { resolve, reject };
      });
      // A failed start is reported to whoever awaits formats(); never unhandled.
      this.ready.catch(() => undefined);
      this.client.ensureStarted();
    }
    return this.ready;
  }

  /**
   * Regenerates `params` in the export worker and returns the files (`lods`: one ZIP of the
   * level GLBs and `options.impostor`).
   */
  async export(
    params: Params,
    volumes: VolumePrimitive[],
    format: ExportFormat,
    options: ExportOptions = {},
  ): Promise<ExportResponse> {
    const formats = await this.formats();
    if (!formats.includes(format)) throw unsupportedFormat(format);
    const request = exportRequest(this.nextId++, params, volumes, format, options);
    return new Promise<ExportResponse>((resolve, reject) => {
      this.client.submit({ request, resolve, reject });
    });
  }

  /** Stops the worker; pending exports fail. */
  dispose(): void {
    this.settleReady?.reject(new ExportError(EXPORT_CANCELLED));
    this.settleReady = null;
    this.client.dispose();
  }
}
