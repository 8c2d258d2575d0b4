/**
 * Test helper: the worker handler over a wasm API with the hash posted at once (no timers),
 * recording every message, and the whole current tree merged from the session's updates.
 */
import type { TreeBuffers, WasmApi } from '../core/types';
import { mergeUpdate } from '../viewer/treeState';
import { createHandler, type HandlerOptions } from '../worker/handler';
import type { ResultResponse, WorkerRequest, WorkerResponse } from '../worker/protocol';
import { loadWasm } from './realWasm';

/** A message the handler posted and what it transferred. */
export interface Sent {
  message: WorkerResponse;
  transfer: Transferable[];
}

/** The handler, its messages, and the merged view of its results. */
export interface Harness {
  sent: Sent[];
  handle: (request: WorkerRequest) => void;
  /** The results posted so far, oldest first. */
  results: () => ResultResponse[];
  /** The last result (throws when the last message of the last request is no result). */
  lastResult: () => ResultResponse;
  /** Every result merged into the whole current tree, with the last hash posted. */
  tree: () => TreeBuffers;
}

/**
 * A handler over `wasm` (the real module by default) that posts hashes synchronously;
 * `options` as for `createHandler` (the default `defer` runs the task at once).
 */
export function harness(
  wasm: WasmApi = loadWasm(),
  options: HandlerOptions & { debug?: undefined } = {},
): Harness {
  const sent: Sent[] = [];
  const handle = createHandler(wasm, (message, transfer) => sent.push({ message, transfer }), {
    defer: (task) => {
      task();
      return () => undefined;
    },
    ...options,
  });
  const results = (): ResultResponse[] =>
    sent.flatMap((s) => (s.message.type === 'result' ? [s.message] : []));
  return {
    sent,
    handle,
    results,
    lastResult: () => {
      const last = sent.filter((s) => s.message.type !== 'hash').at(-1)?.message;
      if (last?.type !== 'result')
        throw new Error(`expected a result, got ${JSON.stringify(last)}`);
      return last;
    },
    tree: () => {
      let tree: TreeBuffers | null = null;
      let hash = '';
      for (const { message } of sent) {
        if (message.type === 'result') {
          tree = mergeUpdate(tree, message);
          hash = message.meta.hash;
        } else if (message.type === 'hash') hash = message.hash;
      }
      if (!tree) throw new Error('no result yet');
      return { ...tree, meta: { ...tree.meta, hash } };
    },
  };
}
