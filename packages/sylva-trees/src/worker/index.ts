/**
 * `sylva-trees/worker`: driving the generator from an app's main thread. Starting the generator
 * worker (or loading the wasm on this thread), adapting a `Worker` to a client's handle, the
 * request and response messages, the scheduler that keeps one tree request in flight, the base
 * client for other requests (leaf inspection, LOD), the mesh-export client, and the buffers of a
 * LOD answer. The worker script itself is `sylva-trees/worker-script`.
 */
export type {
  GeneratorWorkerFactory,
  LeafRequest,
  ReadyInfo,
  ResultResponse,
  WorkerRequest,
  WorkerResponse,
} from './protocol';
export {
  WorkerClient,
  type DropReason,
  type WorkerHandle,
  type WorkerStartOptions,
} from './client';
export { GenerationScheduler, type GeneratorFactory } from './scheduler';
export { DEBUG_WORKER_NAME } from './debugName';
export { startGeneratorWorker } from '../runtime/startWorker';
export { adaptWorker, type EarlyMessages } from '../runtime/workerHandle';
export { loadWasmHere } from '../runtime/inProcess';
export {
  LatestLane,
  POOL_JOB_CANCELLED,
  poolSize,
  WorkerPool,
  type PoolMember,
  type PoolRunOptions,
} from '../runtime/pool';
export {
  EXPORT_CANCELLED,
  EXPORT_TIME_LIMIT_MS,
  ExportClient,
  ExportError,
  exporterCrashed,
  exportRequest,
  exportTimedOut,
  unsupportedFormat,
  type ExportOptions,
} from '../export/exportClient';
export type {
  ExportFormat,
  ExportRequest,
  ExportResponse,
  LeafExport,
} from '../export/exportProtocol';
export {
  QUAD_FLOATS,
  type ClumpBuffers,
  type LodBuffers,
  type LodLevelBuffers,
} from '../lod/types';
export { CELL_DENSITY, clumpLeaves, densityCell } from '../lod/clump';
