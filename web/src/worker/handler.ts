/** Worker-side request handling over an initialised wasm API (no Worker globals; testable in Node). */
import { parseMeta, parsePresets, parseRegistry, toSylvaError } from '../core/parse';
import type { WasmApi } from '../core/types';
import type { ReadyResponse, WorkerRequest, WorkerResponse } from './protocol';

/** Sends a response, transferring the given buffers. */
export type Post = (message: WorkerResponse, transfer: Transferable[]) => void;

/** Builds the `ready` message from the wasm registry, presets and version. */
export function readyMessage(wasm: WasmApi): ReadyResponse {
  return {
    type: 'ready',
    registry: parseRegistry(wasm.registry_json()),
    presets: parsePresets(wasm.presets_json()),
    version: wasm.core_version(),
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

/** Blocks the worker thread for `ms` (debug hook: lets tests hit the scheduler's time limit). */
function busyWait(ms: number, now: () => number): void {
  const end = now() + ms;
  while (now() < end) {
    // spin
  }
}

/** Creates the request handler; after a panic it answers every request with `fatal`. */
export function createHandler(
  wasm: WasmApi,
  post: Post,
  now: () => number = () => performance.now(),
): (request: WorkerRequest) => void {
  let deadMessage: string | null = null;

  const die = (thrown: unknown): void => {
    deadMessage = panicMessage(wasm, thrown);
    post({ type: 'fatal', message: deadMessage }, []);
  };

  return (request) => {
    if (deadMessage !== null) {
      post({ type: 'fatal', message: deadMessage }, []);
      return;
    }
    if (request.type === 'debug-hang') {
      busyWait(request.ms, now);
      post({ type: 'idle' }, []);
      return;
    }
    if (request.type === 'debug-panic') {
      try {
        wasm.debug_panic();
        post({ type: 'fatal', message: 'debug_panic() returned without panicking' }, []);
      } catch (thrown) {
        die(thrown);
      }
      return;
    }
    let tree;
    try {
      tree = wasm.generate(JSON.stringify(request.params));
    } catch (thrown) {
      if (isTrap(thrown)) die(thrown);
      else post({ type: 'error', id: request.id, error: toSylvaError(thrown) }, []);
      return;
    }
    try {
      const positions = tree.positions();
      const normals = tree.normals();
      const uvs = tree.uvs();
      const indices = tree.indices();
      const envelope = tree.envelope_lines();
      const meta = parseMeta(tree.meta_json());
      post({ type: 'result', id: request.id, positions, normals, uvs, indices, envelope, meta }, [
        positions.buffer,
        normals.buffer,
        uvs.buffer,
        indices.buffer,
        envelope.buffer,
      ]);
    } catch (thrown) {
      if (isTrap(thrown)) die(thrown);
      else post({ type: 'error', id: request.id, error: toSylvaError(thrown) }, []);
    } finally {
      try {
        tree.free();
      } catch {
        // freeing after a trap may fail; the instance is discarded anyway
      }
    }
  };
}
