/** Worker-side request handling over an initialised wasm API (no Worker globals; testable in Node). */
import { parseLeafInspection, parsePresets, parseRegistry, toSylvaError } from '../core/parse';
import type { LeafPresetId, Params, WasmApi } from '../core/types';
import { lodsResponse } from '../lod/lodHandler';
import { exportFormatsOf, exportTree } from '../export/exportHandler';
import {
  deferToTimer,
  PREVIEW_BUDGET_MS,
  SessionGenerator,
  type Defer,
  type Post,
} from './generate';
import type { DebugHooks, DebugRequest, DebugResponse } from './debug';
import type { LeafRequest, ReadyResponse, WorkerRequest, WorkerResponse } from './protocol';

export type { Post } from './generate';

/** What the handler posts: the production responses, and a debug worker's `idle`. */
export type HandlerPost = (
  message: WorkerResponse | DebugResponse,
  transfer: Transferable[],
) => void;

/** Builds the `ready` message from the wasm registry, presets and version. */
export function readyMessage(wasm: WasmApi): ReadyResponse {
  return {
    type: 'ready',
    registry: parseRegistry(wasm.registry_json()),
    presets: parsePresets(wasm.presets_json()),
    version: wasm.core_version(),
    leafPresets: wasm.leaf_presets_json ? parsePresets<LeafPresetId>(wasm.leaf_presets_json()) : [],
    exportFormats: exportFormatsOf(wasm),
  };
}

/**
 * Message of a wasm trap: the core's recorded panic text, else the trap itself (a failed
 * allocation aborts without a panic message, as `unreachable`; a memory fault reads
 * `memory access out of bounds`).
 */
function panicMessage(wasm: WasmApi, thrown: unknown): string {
  let recorded: string | undefined;
  try {
    recorded = wasm.take_panic();
  } catch {
    recorded = undefined;
  }
  if (recorded) return recorded;
  const text = thrown instanceof Error ? thrown.message : String(thrown);
  return `WebAssembly trap (${text || 'no message'}): the generator aborted, possibly out of memory`;
}

/**
 * Whether a throw means the wasm instance is no longer usable: any trap (`unreachable` from a
 * panic or a failed allocation, `memory access out of bounds`, ...), or a stack overflow, which
 * leaves Rust's shadow stack mid-frame.
 */
export function isTrap(thrown: unknown): boolean {
  if (thrown instanceof WebAssembly.RuntimeError) return true;
  return thrown instanceof RangeError && /call stack/i.test(thrown.message);
}

/** Answers a leaf inspector request (throws what the core throws). */
function handleLeaf(wasm: WasmApi, request: LeafRequest, post: Post): void {
  if (!wasm.leaf_inspect) throw new Error('this generator has no leaf inspector');
  const text = wasm.leaf_inspect(
    JSON.stringify(request.params),
    request.step,
    request.triangulation,
  );
  post({ type: 'leaf', id: request.id, ...parseLeafInspection(text) }, []);
}

/** Settings of [`createHandler`]. */
export interface HandlerOptions {
  /** Clock of the debug hang (default `performance.now`). */
  now?: () => number;
  /**
   * Accept the debug messages, answered by these hooks (`debug.ts`: a debug build's worker
   * started with the debug flag, and tests); without them they are refused.
   */
  debug?: DebugHooks;
  /** How a result's hash is scheduled after it (default: a zero-delay timer). */
  defer?: Defer;
  /** Bark time above which a drag gets a preview (ms; default [`PREVIEW_BUDGET_MS`]). */
  previewBudgetMs?: number;
  /**
   * Generates these parameters before the first request (the worker does it for the default
   * tree while the page loads): the wasm code is compiled and warm, and a first request for
   * the same tree is answered without generating it again.
   */
  prime?: Params;
}

/**
 * Creates the request handler: a typed error answers the request and the worker stays usable;
 * a trap is fatal, and after it every request is answered with `fatal`. The debug messages are
 * refused (as fatal) unless `options.debug` is set.
 */
export function createHandler(
  wasm: WasmApi,
  post: Post,
  options?: HandlerOptions & { debug?: undefined },
): (request: WorkerRequest) => void;
export function createHandler(
  wasm: WasmApi,
  post: HandlerPost,
  options: HandlerOptions,
): (request: WorkerRequest | DebugRequest) => void;
export function createHandler(
  wasm: WasmApi,
  post: Post | HandlerPost,
  options: HandlerOptions = {},
): (request: WorkerRequest | DebugRequest) => void {
  const now = options.now ?? (() => performance.now());
  const debug = options.debug;
  let deadMessage: string | null = null;
  const die = (thrown: unknown): void => {
    deadMessage = panicMessage(wasm, thrown);
    post({ type: 'fatal', message: deadMessage }, []);
  };
  const generator = new SessionGenerator(wasm, post, {
    defer: options.defer ?? deferToTimer,
    previewBudgetMs: options.previewBudgetMs ?? PREVIEW_BUDGET_MS,
    onDeferredThrow: (thrown) => {
      if (isTrap(thrown)) die(thrown);
    },
  });
  if (options.prime) {
    try {
      generator.prime(options.prime);
    } catch (thrown) {
      // A failed warm-up changes nothing: the first request generates cold.
      if (isTrap(thrown)) die(thrown);
    }
  }

  /** Runs one request; what it throws becomes the request's error, or kills the worker. */
  const run = (id: number | null, work: () => void): void => {
    try {
      work();
    } catch (thrown) {
      if (isTrap(thrown) || id === null) die(thrown);
      else post({ type: 'error', id, error: toSylvaError(thrown) }, []);
    }
  };

  return (request) => {
    if (deadMessage !== null) {
      post({ type: 'fatal', message: deadMessage }, []);
      return;
    }
    switch (request.type) {
      case 'generate':
        run(request.id, () => generator.handle(request));
        return;
      case 'leaf':
        run(request.id, () => handleLeaf(wasm, request, post));
        return;
      case 'export':
        run(request.id, () => exportTree(wasm, request, post));
        return;
      case 'lods':
        run(request.id, () => post(...lodsResponse(wasm, request)));
        return;
      case 'debug-hang':
      case 'debug-panic':
        if (!debug) break;
        // A debug handler's `post` takes the debug responses (see the overloads).
        debug.handle(request, {
          wasm,
          post: post as HandlerPost,
          now,
          fatalOnThrow: (work) => run(null, work),
        });
        return;
      default: {
        const unknown: never = request;
        throw new Error(`unknown request ${JSON.stringify(unknown)}`);
      }
    }
    throw new Error(`${request.type} needs a worker started with the debug flag`);
  };
}
