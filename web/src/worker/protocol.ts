/** Typed message protocol between the main thread and the generator worker. */
import type { ParamSpec, Params, Preset, SylvaError, TreeBuffers } from '../core/types';

/** Ask the worker to generate a tree; `id` routes the answer. */
export interface GenerateRequest {
  type: 'generate';
  id: number;
  params: Params;
}

/** Ask the worker to panic on purpose (tests of the recovery path). */
export interface DebugPanicRequest {
  type: 'debug-panic';
}

/** Ask the worker to busy-loop for `ms` (tests of the time limit; debug hook only). */
export interface DebugHangRequest {
  type: 'debug-hang';
  ms: number;
}

/** Main thread → worker. */
export type WorkerRequest = GenerateRequest | DebugPanicRequest | DebugHangRequest;

/** Sent once after the wasm is initialised. */
export interface ReadyResponse {
  type: 'ready';
  registry: ParamSpec[];
  presets: Preset[];
  version: string;
}

/** A generated tree; the five arrays arrive as transferred buffers. */
export interface ResultResponse extends TreeBuffers {
  type: 'result';
  id: number;
}

/** A typed, recoverable error for one request (the worker stays usable). */
export interface ErrorResponse {
  type: 'error';
  id: number;
  error: SylvaError;
}

/** The worker is unusable (wasm panic or failed init) and must be recreated. */
export interface FatalResponse {
  type: 'fatal';
  message: string;
}

/** A `debug-hang` request ended (it ran shorter than the time limit). */
export interface IdleResponse {
  type: 'idle';
}

/** Worker → main thread. */
export type WorkerResponse =
  ReadyResponse | ResultResponse | ErrorResponse | FatalResponse | IdleResponse;

/** What `ready` carries, as seen by the app. */
export type ReadyInfo = Omit<ReadyResponse, 'type'>;
