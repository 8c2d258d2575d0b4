/**
 * Typed message protocol between the main thread and the generator worker (the production
 * messages; the test hooks' messages are in `debug.ts`, accepted by a debug worker only).
 */
import type { Edit } from '../core/edits';
import type {
  LeafInspection,
  LeafPreset,
  ParamSpec,
  Params,
  Preset,
  SylvaError,
  TreeUpdate,
  VolumePrimitive,
} from '../core/types';
import type { WorkerFactory } from './client';
import type { LodsRequest, LodsResponse } from '../lod/types';
import type { ExportFormat, ExportRequest, ExportResponse } from '../export/exportProtocol';

/** Ask the worker to generate a tree; `id` routes the answer. */
export interface GenerateRequest {
  type: 'generate';
  id: number;
  params: Params;
  /** Growth mode: the user's volume primitives (sent as the core's `"volumes"` key). */
  volumes?: VolumePrimitive[];
  /** The hand edit list (sent as the core's `"edits"` key; absent when empty). */
  edits?: Edit[];
  /**
   * A slider is being dragged: the worker may answer with a preview bark when the full one
   * would take longer than a frame (the full tree follows when the drag settles).
   */
  preview?: boolean;
  /**
   * Send the end grain of the tree's bark type with this answer even if the tree has no cut
   * yet (the app's Cut tool is active): the bake (about 0.1 s) then happens before the first
   * cut, whose answer needs none. Sent once per bark type either way.
   */
  endGrain?: boolean;
}

/** Ask the worker for the leaf inspector's drawing of the `leaf_*` params after growth `step` (-1: finished). */
export interface LeafRequest {
  type: 'leaf';
  id: number;
  params: Params;
  step: number;
  /** Draw the triangulation. */
  triangulation: boolean;
}

/** Main thread → worker. */
export type WorkerRequest = GenerateRequest | LeafRequest | LodsRequest | ExportRequest;

/** Sent once after the wasm is initialised. */
export interface ReadyResponse {
  type: 'ready';
  registry: ParamSpec[];
  presets: Preset[];
  version: string;
  /** The leaf presets (`leaf_presets_json`), for the leaf inspector. */
  leafPresets?: LeafPreset[];
  /** Mesh formats the core can export (absent: none). */
  exportFormats?: ExportFormat[];
  /**
   * Threads a generation uses: 2 with the threaded core and its helper worker (a cross-origin
   * isolated page), 1 otherwise (absent: 1).
   */
  threads?: number;
}

/**
 * The tree for request `id`: the meta, and only the arrays that changed since the worker's
 * previous result (transferred buffers; see `TreeUpdate`).
 */
export interface ResultResponse extends TreeUpdate {
  type: 'result';
  id: number;
}

/**
 * The content hash of result `id`, computed after the result was posted (never for a preview).
 * It may never come when a newer request superseded that tree.
 */
export interface HashResponse {
  type: 'hash';
  id: number;
  hash: string;
}

/** A typed, recoverable error for one request (the worker stays usable). */
export interface ErrorResponse {
  type: 'error';
  id: number;
  error: SylvaError;
}

/** Growth progress of request `id` (fraction 0..1 of the iteration cap), posted while busy. */
export interface ProgressResponse {
  type: 'progress';
  id: number;
  fraction: number;
}

/** The worker is unusable (wasm panic or failed init) and must be recreated. */
export interface FatalResponse {
  type: 'fatal';
  message: string;
}

/** Worker → main thread. */
export type WorkerResponse =
  | ReadyResponse
  | ResultResponse
  | HashResponse
  | ErrorResponse
  | FatalResponse
  | ProgressResponse
  | LeafResponse
  | LodsResponse
  | ExportResponse;

/** The leaf inspector's answer to request `id`: the SVG text and counts. */
export interface LeafResponse extends LeafInspection {
  type: 'leaf';
  id: number;
}

/** What `ready` carries, as seen by the app. */
export type ReadyInfo = Omit<ReadyResponse, 'type'>;

/** Starts a generator worker for a client of the production requests. */
export type GeneratorWorkerFactory = WorkerFactory<WorkerRequest, WorkerResponse>;
