/** React hook wiring the scheduler to the viewer (mesh via refs) and to small React state. */
import { useCallback, useEffect, useRef, useState, type RefObject } from 'react';
import type { Edit, Params, SylvaError, VolumePrimitive } from 'sylva-trees/core';
import { createGeneratorWorker } from '../createWorker';
import type { TreeViewer } from '../viewer/TreeViewer';
import { GenerationScheduler, type ReadyInfo } from 'sylva-trees/worker';
import { debugMode, installDebugHook } from './debugHook';
import { RequestLog, showResult } from './requestLog';
import { StatsStore } from './statsStore';

export type { TreeStats } from './statsStore';

/** What the app sees of the generator. */
export interface Generator {
  /** Stats and busy state, read by the overlay alone (no app re-render per tree). */
  stats: StatsStore;
  error: SylvaError | null;
  restarts: number;
  /**
   * Requests a tree with its growth volumes and hand edits; `frame` re-frames the camera when it
   * (or a newer one) arrives; `interactive` marks a step of a drag (a preview may answer; see
   * `settle`).
   */
  request(params: Params, frame: boolean, shape?: TreeShape): void;
  /** The drag ended: the full tree follows the preview, if one is shown. */
  settle(): void;
  clearError(): void;
  /** Growth progress (0..1) of the generation in flight, null when none reports progress. */
  progress: number | null;
  /** Cancels the generation in flight (fresh worker; the last tree stays). */
  cancel(): void;
  /**
   * The Cut tool was chosen: the last tree is asked for again with its end grain, so the worker
   * bakes it while the user aims and the first cut answers without the bake.
   */
  prepareCut(): void;
}

/** What a request carries beside the params. */
export interface TreeShape {
  volumes?: VolumePrimitive[];
  edits?: readonly Edit[];
  interactive?: boolean;
}

/** The editor's current volumes and edits, read for the first request. */
export interface InitialShape {
  volumesRef: RefObject<VolumePrimitive[]>;
  editsRef: RefObject<Edit[]>;
}

/**
 * Starts the worker on mount. `onReady` fires once with the registry and presets and returns the
 * initial params, which are requested right away.
 */
export function useGenerator(
  viewer: RefObject<TreeViewer | null>,
  onReady: (info: ReadyInfo) => Params,
  /** Volume primitives and edits of the initial request (read right after `onReady`). */
  initial?: InitialShape,
): Generator {
  const [progress, setProgress] = useState<number | null>(null);
  const [stats] = useState(() => new StatsStore());
  const [error, setError] = useState<SylvaError | null>(null);
  const [restarts, setRestarts] = useState(0);
  const schedulerRef = useRef<GenerationScheduler | null>(null);
  /** The last tree asked for (the worker's, once answered). */
  const lastRef = useRef<{ params: Params; shape: TreeShape } | null>(null);
  const onReadyRef = useRef(onReady);
  const [log] = useState(() => new RequestLog());

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
            const params = onReadyRef.current(info);
            const edits = initial?.editsRef.current ?? [];
            const volumes = initial?.volumesRef.current;
            lastRef.current = { params, shape: { volumes, edits } };
            log.requested(scheduler.request(params, volumes, { edits }));
          }
        },
        onResult: (result) => {
          showResult(result, log, stats, (tree, frame) => viewer.current?.apply(tree, frame));
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
      // Only the debug build's worker (`vite build --mode debug`, web/dist-debug) has the test
      // hooks that `panic` and `hang` drive; the shipped app leaves them out.
      ...(import.meta.env.MODE === 'debug'
        ? { panic: () => scheduler.debugPanic(), hang: (ms: number) => scheduler.debugHang(ms) }
        : {}),
      setTimeLimit: (ms) => {
        scheduler.timeLimitMs = ms;
      },
      trees: () => [...log.trees],
      settleWhenIdle: (on) => {
        scheduler.settleWhenIdle = on;
      },
    });
    return () => {
      uninstall();
      scheduler.dispose();
      if (schedulerRef.current === scheduler) schedulerRef.current = null;
    };
  }, [viewer, initial, stats, log]);

  const request = useCallback(
    (params: Params, frame: boolean, shape: TreeShape = {}) => {
      const scheduler = schedulerRef.current;
      if (!scheduler) return;
      lastRef.current = { params, shape };
      const { volumes, edits, interactive = false } = shape;
      log.requested(scheduler.request(params, volumes, { interactive, edits }), frame);
    },
    [log],
  );

  const prepareCut = useCallback(() => {
    const scheduler = schedulerRef.current;
    const last = lastRef.current;
    if (!scheduler || !last) return;
    // At full quality: a drag not yet settled settles here.
    const { volumes, edits } = last.shape;
    log.requested(scheduler.request(last.params, volumes, { edits, endGrain: true }));
  }, [log]);

  const settle = useCallback(() => {
    const id = schedulerRef.current?.settle();
    if (id != null) log.requested(id);
  }, [log]);

  const clearError = useCallback(() => setError(null), []);

  const cancel = useCallback(() => {
    schedulerRef.current?.cancel();
  }, []);

  return { stats, error, restarts, request, settle, clearError, progress, cancel, prepareCut };
}
