/**
 * The studio's generation pool: one worker per core, at most `poolSize` (`WorkerPool`), apart
 * from the editor's own worker, for the independent jobs: the LOD panel's levels of detail
 * (latest-wins, [`LodClient`] in `lod/lodClient.ts`), the Export menu's mesh exports and the
 * forest's trees. Each worker starts with the first job that needs it; the app disposes of the
 * pool when it unmounts. Jobs run in the order given, each on the first free worker, so the
 * editor's worker only ever generates the tree being edited and stays responsive while the pool
 * works (e2e/tests/pool.spec.ts).
 */
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';
import {
  type ExportFormat,
  type ExportOptions,
  type ExportResponse,
  type GeneratorWorkerFactory,
  type LodBuffers,
  poolSize,
  type PoolRunOptions,
  WorkerPool,
} from 'sylva-trees/worker';
import { GenerationClient } from './generationClient';

/** What runs a mesh export (the Export menu's items, `export/meshExport.ts`). */
export interface Exporter {
  export(
    params: Params,
    volumes: VolumePrimitive[],
    format: ExportFormat,
    options?: ExportOptions,
  ): Promise<ExportResponse>;
}

/** A levels-of-detail job. */
export interface LodsOptions extends PoolRunOptions {
  /** Every level also comes with its leaves baked into one mesh (the forest draws them so). */
  bakeLeaves?: boolean;
}

/** The pool's state, for the debug hook (`window.__sylva.pool()`) and tests. */
export interface PoolState {
  size: number;
  /** Workers started so far. */
  started: number;
  /** Jobs running, per worker (0 or 1). */
  load: number[];
  /** Jobs waiting for a free worker. */
  waiting: number;
  /** Jobs given, per kind, since the pool was made. */
  given: { lods: number; export: number };
}

/** See the module docs. */
export class GenerationPool implements Exporter {
  /** The workers (exposed for latest-wins lanes over them). */
  readonly workers: WorkerPool<GenerationClient>;
  private readonly given = { lods: 0, export: 0 };

  /** `size`: the number of workers (default: one per core, at most 4). */
  constructor(
    factory: GeneratorWorkerFactory,
    size = poolSize(typeof navigator === 'undefined' ? 1 : navigator.hardwareConcurrency),
  ) {
    this.workers = new WorkerPool(() => new GenerationClient(factory), size);
  }

  /** Number of workers. */
  get size(): number {
    return this.workers.size;
  }

  /** See [`PoolState`]. */
  state(): PoolState {
    return {
      size: this.workers.size,
      started: this.workers.started,
      load: [...this.workers.load],
      waiting: this.workers.waiting,
      given: { ...this.given },
    };
  }

  /** The tree of `params` and its levels of detail, generated in a pool worker. */
  lods(
    params: Params,
    volumes?: VolumePrimitive[],
    edits?: readonly Edit[],
    { bakeLeaves = false, signal }: LodsOptions = {},
  ): Promise<LodBuffers> {
    this.given.lods++;
    return this.workers.run((w) => w.lods(params, volumes, edits, bakeLeaves), { signal });
  }

  /** Regenerates `params` in a pool worker and exports it (the editor's worker is not asked). */
  export(
    params: Params,
    volumes: VolumePrimitive[],
    format: ExportFormat,
    options: ExportOptions = {},
  ): Promise<ExportResponse> {
    this.given.export++;
    return this.workers.run((w) => w.export(params, volumes, format, options));
  }

  /** Terminates every worker; waiting and running jobs reject. */
  dispose(): void {
    this.workers.dispose();
  }
}
