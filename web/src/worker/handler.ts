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

/** Message of a wasm panic: the core's recorded panic text, else the trap's message. */
function panicMessage(wasm: WasmApi, thrown: unknown): string {
  let recorded: string | undefined;
  try {
    recorded = wasm.take_panic();
  } catch {
    recorded = undefined;
  }
  if (recorded) return recorded;
  return thrown instanceof Error ? thrown.message : String(thrown);
}

/** Creates the request handler; after a panic it answers every request with `fatal`. */
export function createHandler(wasm: WasmApi, post: Post): (request: WorkerRequest) => void {
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
      if (thrown instanceof WebAssembly.RuntimeError) die(thrown);
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
      if (thrown instanceof WebAssembly.RuntimeError) die(thrown);
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
