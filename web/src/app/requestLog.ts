/**
 * The generator's bookkeeping on the main thread (plain module): when each request was made,
 * which answer re-frames the camera, and the log of applied trees that the debug hook exposes
 * (benchmarks read the answer times from it).
 */
import type { ResultResponse } from 'sylva-trees/worker';
import type { TreeApplied } from './debugHook';
import { emitDebug } from './debugHook';
import type { StatsStore } from './statsStore';

/** Most trees kept in the log. */
const TREE_LOG = 200;

/** See the module docs. */
export class RequestLog {
  /** When each request was made; a result removes its own and every older (superseded) one. */
  private readonly requestedAt = new Map<number, number>();
  private frameFromId = 0;
  private hadResult = false;
  /** Applied trees, oldest first. */
  readonly trees: TreeApplied[] = [];

  /** Request `id` was made now; `frame`: its answer (or a newer one) re-frames the camera. */
  requested(id: number, frame = false): void {
    this.requestedAt.set(id, performance.now());
    if (frame) this.frameFromId = id;
  }

  /** The answer to `id` arrived: whether it re-frames (the first tree does) and when it was asked. */
  answered(id: number): { frame: boolean; requestedAt: number | null } {
    const frame = !this.hadResult || (this.frameFromId > 0 && id >= this.frameFromId);
    if (frame) this.frameFromId = 0;
    this.hadResult = true;
    const requestedAt = this.requestedAt.get(id) ?? null;
    for (const old of this.requestedAt.keys()) {
      if (old <= id) this.requestedAt.delete(old); // this one and the superseded
    }
    return { frame, requestedAt };
  }

  /** Logs a tree in the scene and announces it (`sylva:applied`). */
  applied(tree: TreeApplied, received: number, workerMs: number): void {
    this.trees.push(tree);
    if (this.trees.length > TREE_LOG) this.trees.splice(0, this.trees.length - TREE_LOG);
    emitDebug('applied', { kind: 'tree', ...tree, received, workerMs });
  }
}

/**
 * Shows `result`: applies it to the viewer (`apply`), logs it and updates the stats. The upload
 * and draw happen on the next animation frame (never a synchronous draw here: that would block
 * the main thread while a slider is dragged).
 */
export function showResult(
  result: ResultResponse,
  log: RequestLog,
  stats: StatsStore,
  apply: (result: ResultResponse, frame: boolean) => void,
): void {
  const received = performance.now();
  const { frame, requestedAt } = log.answered(result.id);
  apply(result, frame);
  const built = performance.now();
  const { vertices, triangles, hash, total_ms, stems } = result.meta;
  const preview = result.meta.preview === true;
  log.applied({ id: result.id, at: built, requestedAt, preview }, received, total_ms);
  const roundTripMs = requestedAt === null ? null : built - requestedAt;
  const drawMs = null;
  stats.set({
    stats: { vertices, triangles, hash, total_ms, stems, roundTripMs, drawMs, preview },
  });
}
