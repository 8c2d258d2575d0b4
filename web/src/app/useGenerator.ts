/** React hook wiring the scheduler to the viewer (mesh via refs) and to small React state. */
import { useCallback, useEffect, useRef, useState, type RefObject } from 'react';
import type { Params, SylvaError, TreeMeta } from '../core/types';
import { createModuleWorker } from '../createWorker';
import type { TreeViewer } from '../viewer/TreeViewer';
import type { ReadyInfo } from '../worker/protocol';
import { GenerationScheduler } from '../worker/scheduler';
import { installDebugHook } from './debugHook';

/** Per-tree numbers shown in the stats overlay. */
export type TreeStats = Pick<TreeMeta, 'vertices' | 'triangles' | 'hash' | 'total_ms' | 'stems'>;

/** What the app sees of the generator. */
export interface Generator {
  stats: TreeStats | null;
  error: SylvaError | null;
  busy: boolean;
  restarts: number;
  /** Requests a tree; `frame` re-frames the camera when it (or a newer one) arrives. */
  request(params: Params, frame: boolean): void;
  clearError(): void;
}

/**
 * Starts the worker on mount. `onReady` fires once with the registry and presets and returns the
 * initial params, which are requested right away.
 */
export function useGenerator(
  viewer: RefObject<TreeViewer | null>,
  onReady: (info: ReadyInfo) => Params,
): Generator {
  const [stats, setStats] = useState<TreeStats | null>(null);
  const [error, setError] = useState<SylvaError | null>(null);
  const [busy, setBusy] = useState(false);
  const [restarts, setRestarts] = useState(0);
  const schedulerRef = useRef<GenerationScheduler | null>(null);
  const frameFromIdRef = useRef(0);
  const hadResultRef = useRef(false);
  const onReadyRef = useRef(onReady);

  useEffect(() => {
    onReadyRef.current = onReady;
  }, [onReady]);

  useEffect(() => {
    let announced = false;
    const scheduler = new GenerationScheduler(createModuleWorker, {
      onReady: (info, restartCount) => {
        setRestarts(restartCount);
        if (!announced) {
          announced = true;
          scheduler.request(onReadyRef.current(info));
        }
      },
      onResult: (result) => {
        const frame =
          !hadResultRef.current ||
          (frameFromIdRef.current > 0 && result.id >= frameFromIdRef.current);
        if (frame) frameFromIdRef.current = 0;
        hadResultRef.current = true;
        viewer.current?.setTree(result, frame);
        const { vertices, triangles, hash, total_ms, stems } = result.meta;
        setStats({ vertices, triangles, hash, total_ms, stems });
        setError(null);
      },
      onError: (err) => setError(err),
      onBusyChange: setBusy,
    });
    schedulerRef.current = scheduler;
    const uninstall = installDebugHook({
      panic: () => scheduler.debugPanic(),
      hang: (ms) => scheduler.debugHang(ms),
      setTimeLimit: (ms) => {
        scheduler.timeLimitMs = ms;
      },
    });
    return () => {
      uninstall();
      scheduler.dispose();
      if (schedulerRef.current === scheduler) schedulerRef.current = null;
    };
  }, [viewer]);

  const request = useCallback((params: Params, frame: boolean) => {
    const scheduler = schedulerRef.current;
    if (!scheduler) return;
    const id = scheduler.request(params);
    if (frame) frameFromIdRef.current = id;
  }, []);

  const clearError = useCallback(() => setError(null), []);

  return { stats, error, busy, restarts, request, clearError };
}
