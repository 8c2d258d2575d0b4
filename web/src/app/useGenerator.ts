/** React hook wiring the scheduler to the viewer (mesh via refs) and to small React state. */
import { useCallback, useEffect, useRef, useState, type RefObject } from 'react';
import type { Params, SylvaError, VolumePrimitive } from '../core/types';
import { createGeneratorWorker } from '../createWorker';
import type { TreeViewer } from '../viewer/TreeViewer';
import type { ReadyInfo } from '../worker/protocol';
import { GenerationScheduler } from '../worker/scheduler';
import { debugMode, emitDebug, installDebugHook, type TreeApplied } from './debugHook';
import { StatsStore } from './statsStore';

export type { TreeStats } from './statsStore';

/** What the app sees of the generator. */
export interface Generator {
  /** Stats and busy state, read by the overlay alone (no app re-render per tree). */
  stats: StatsStore;
  error: SylvaError | null;
  restarts: number;
  /**
   * Requests a tree; `frame` re-frames the camera when it (or a newer one) arrives;
   * `interactive` marks a step of a drag (a preview may answer; see `settle`).
   */
  request(params: Params, frame: boolean, volumes?: VolumePrimitive[], interactive?: boolean): void;
  /** The drag ended: the full tree follows the preview, if one is shown. */
  settle(): void;
  clearError(): void;
  /** Growth progress (0..1) of the generation in flight, null when none reports progress. */
  progress: number | null;
  /** Cancels the generation in flight (fresh worker; the last tree stays). */
  cancel(): void;
}

/** Most trees kept in the debug hook's log. */
const TREE_LOG = 200;

/**
 * Starts the worker on mount. `onReady` fires once with the registry and presets and returns the
 * initial params, which are requested right away.
 */
export function useGenerator(
  viewer: RefObject<TreeViewer | null>,
  onReady: (info: ReadyInfo) => Params,
  /** Volume primitives of the initial request (read right after `onReady`). */
  initialVolumes?: RefObject<VolumePrimitive[]>,
): Generator {
  const [progress, setProgress] = useState<number | null>(null);
  const [stats] = useState(() => new StatsStore());
  const [error, setError] = useState<SylvaError | null>(null);
  const [restarts, setRestarts] = useState(0);
  const schedulerRef = useRef<GenerationScheduler | null>(null);
  const frameFromIdRef = useRef(0);
  const hadResultRef = useRef(false);
  const onReadyRef = useRef(onReady);
  /** When each request was made; a result removes its own and every older (superseded) one. */
  const requestedAtRef = useRef(new Map<number, number>());
  /** Applied trees, for the debug hook (benchmarks read the answer times). */
  const treeLogRef = useRef<TreeApplied[]>([]);

  useEffect(() => {
    onReadyRef.current = onReady;
  }, [onReady]);

  useEffect(() => {
    let announced = false;
    const scheduler = new GenerationScheduler(
      createGeneratorWorker,
      {
        onReady: (info, restartCount) => {
          setRestarts(restartCount);
          if (!announced) {
            announced = true;
            const initial = onReadyRef.current(info);
            requestedAtRef.current.set(
              scheduler.request(initial, initialVolumes?.current),
              performance.now(),
            );
          }
        },
        onResult: (result) => {
          const received = performance.now();
          const frame =
            !hadResultRef.current ||
            (frameFromIdRef.current > 0 && result.id >= frameFromIdRef.current);
          if (frame) frameFromIdRef.current = 0;
          hadResultRef.current = true;
          const requestedAt = requestedAtRef.current.get(result.id);
          for (const id of requestedAtRef.current.keys()) {
            if (id <= result.id) requestedAtRef.current.delete(id); // this one and the superseded
          }
          viewer.current?.apply(result, frame);
          const built = performance.now();
          const { vertices, triangles, hash, total_ms, stems } = result.meta;
          const preview = result.meta.preview === true;
          const log = treeLogRef.current;
          const applied = { id: result.id, at: built, requestedAt: requestedAt ?? null, preview };
          log.push(applied);
          if (log.length > TREE_LOG) log.splice(0, log.length - TREE_LOG);
          emitDebug('applied', {
            kind: 'tree',
            ...applied,
            received,
            workerMs: result.meta.total_ms,
          });
          // The upload and draw happen on the next animation frame (never a synchronous draw
          // here: that would block the main thread while a slider is dragged).
          const roundTripMs = requestedAt === undefined ? null : built - requestedAt;
          stats.set({
            stats: {
              vertices,
              triangles,
              hash,
              total_ms,
              stems,
              roundTripMs,
              drawMs: null,
              preview,
            },
          });
          setError(null);
        },
        onHash: (hash) => {
          viewer.current?.setHash(hash);
          stats.setHash(hash);
        },
        onError: (err) => setError(err),
        onBusyChange: (busy) => stats.set({ busy }),
        onProgress: (fraction) => setProgress(fraction),
      },
      { debug: debugMode() },
    );
    schedulerRef.current = scheduler;
    const uninstall = installDebugHook({
      panic: () => scheduler.debugPanic(),
      hang: (ms) => scheduler.debugHang(ms),
      setTimeLimit: (ms) => {
        scheduler.timeLimitMs = ms;
      },
      trees: () => [...treeLogRef.current],
      settleWhenIdle: (on) => {
        scheduler.settleWhenIdle = on;
      },
    });
    return () => {
      uninstall();
      scheduler.dispose();
      if (schedulerRef.current === scheduler) schedulerRef.current = null;
    };
  }, [viewer, initialVolumes, stats]);

  const request = useCallback(
    (params: Params, frame: boolean, volumes?: VolumePrimitive[], interactive = false) => {
      const scheduler = schedulerRef.current;
      if (!scheduler) return;
      const id = scheduler.request(params, volumes, { interactive });
      requestedAtRef.current.set(id, performance.now());
      if (frame) frameFromIdRef.current = id;
    },
    [],
  );

  const settle = useCallback(() => {
    const id = schedulerRef.current?.settle();
    if (id != null) requestedAtRef.current.set(id, performance.now());
  }, []);

  const clearError = useCallback(() => setError(null), []);

  const cancel = useCallback(() => {
    schedulerRef.current?.cancel();
  }, []);

  return { stats, error, restarts, request, settle, clearError, progress, cancel };
}
