/**
 * Main-thread client of the mesh export: a worker of its own (started on first use, so an
 * export never waits behind or cancels the interactive generation), which reports the formats
 * the core supports in its `ready` message.
 */
import type { Params, SylvaError, VolumePrimitive } from '../core/types';
import type { WorkerFactory, WorkerHandle } from '../worker/scheduler';
import type { ExportFormat, ExportResponse, LeafExport } from './exportProtocol';

/** Longest an export may take (ms). */
export const EXPORT_TIME_LIMIT_MS = 60_000;

interface Pending {
  resolve(response: ExportResponse): void;
  reject(error: Error): void;
  timer: ReturnType<typeof setTimeout>;
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

/** Owns the export worker. */
export class ExportClient {
  private worker: WorkerHandle | null = null;
  private ready: Promise<ExportFormat[]> | null = null;
  private readonly pending = new Map<number, Pending>();
  private nextId = 1;
  private failReady: ((error: Error) => void) | null = null;

  constructor(private readonly factory: WorkerFactory) {}

  /** The formats the core can export (starts the worker). */
  formats(): Promise<ExportFormat[]> {
    if (!this.ready) this.start();
    return this.ready ?? Promise.resolve([]);
  }

  /** Regenerates `params` in the export worker and returns the files. */
  async export(
    params: Params,
    volumes: VolumePrimitive[],
    format: ExportFormat,
    options: { leaves?: LeafExport; name?: string } = {},
  ): Promise<ExportResponse> {
    const formats = await this.formats();
    if (!formats.includes(format)) {
      throw new ExportError(`This Sylva core cannot export ${format.toUpperCase()} yet.`);
    }
    const worker = this.worker;
    if (!worker) throw new ExportError('The export worker stopped.');
    const id = this.nextId++;
    return new Promise<ExportResponse>((resolve, reject) => {
      const timer = setTimeout(() => {
        this.fail(new ExportError(`The export took longer than ${EXPORT_TIME_LIMIT_MS / 1000} s.`));
      }, EXPORT_TIME_LIMIT_MS);
      this.pending.set(id, { resolve, reject, timer });
      worker.post({
        type: 'export',
        id,
        params,
        format,
        ...(volumes.length > 0 ? { volumes } : {}),
        ...(options.leaves ? { leaves: options.leaves } : {}),
        ...(options.name ? { name: options.name } : {}),
      });
    });
  }

  /** Stops the worker; pending exports fail. */
  dispose(): void {
    this.fail(new ExportError('The export was cancelled.'));
  }

  private start(): void {
    this.ready = new Promise<ExportFormat[]>((resolve, reject) => {
      this.failReady = reject;
      this.worker = this.factory(
        (response) => {
          if (response.type === 'ready') {
            this.failReady = null;
            resolve(response.exportFormats ?? []);
          } else if (response.type === 'exported' || response.type === 'error') {
            const entry = this.pending.get(response.id);
            if (!entry) return;
            this.pending.delete(response.id);
            clearTimeout(entry.timer);
            if (response.type === 'exported') entry.resolve(response);
            else entry.reject(new ExportError(response.error.message, response.error));
          } else if (response.type === 'fatal') {
            this.fail(new ExportError(`The exporter crashed: ${response.message}`));
          }
        },
        (message) => this.fail(new ExportError(`The export worker failed: ${message}`)),
      );
    });
    // A failed start is reported to whoever awaits formats(); never unhandled.
    this.ready.catch(() => undefined);
  }

  /** Fails everything in flight and drops the worker (the next call starts a fresh one). */
  private fail(error: Error): void {
    this.worker?.terminate();
    this.worker = null;
    this.failReady?.(error);
    this.failReady = null;
    this.ready = null;
    for (const entry of this.pending.values()) {
      clearTimeout(entry.timer);
      entry.reject(error);
    }
    this.pending.clear();
  }
}
