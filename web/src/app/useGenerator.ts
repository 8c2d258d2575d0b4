/** React hook wiring the scheduler to the viewer (mesh via refs) and to small React state. */
import { useCallback, useEffect, useRef, useState, type RefObject } from 'react';
import type { Params, SylvaError, TreeMeta, VolumePrimitive } from '../core/types';
import { createModuleWorker } from '../createWorker';
import type { TreeViewer } from '../viewer/TreeViewer';
import type { ReadyInfo } from '../worker/protocol';
import { GenerationScheduler } from '../worker/scheduler';
import { installDebugHook } from './debugHook';

/** Per-tree numbers shown in the stats overlay. */
export type TreeStats = Pick<TreeMeta, 'vertices' | 'triangles' | 'hash' | 'total_ms' | 'stems'> & {
  /** Request to geometry built on the main thread: generation + transfer + BufferGeometry (ms). */
  roundTripMs: number | null;
  /** GPU upload + draw time when measured (null: drawn on the next animation frame). */
  drawMs: number | null;
};

/** What the app sees of the generator. */
export interface Generator {
  stats: TreeStats | null;
  error: SylvaError | null;
  busy: boolean;
  restarts: number;
  /** Requests a tree; `frame` re-frames the camera when it (or a newer one) arrives. */
  request(params: Params, frame: boolean, volumes?: VolumePrimitive[]): void;
  clearError(): void;
  /** Growth progress (0..1) of the generation in flight, null when none reports progress. */
  progress: number | null;
  /** Cancels the generation in flight (fresh worker; the last tree stays). */
  cancel(): void;
}

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
  const [stats, setStats] = useState<TreeStats | null>(null);
  const [error, setError] = useState<SylvaError | null>(null);
  const [busy, setBusy] = useState(false);
  const [restarts, setRestarts] = useState(0);
  const schedulerRef = useRef<GenerationScheduler | null>(null);
  const frameFromIdRef = useRef(0);
  const hadResultRef = useRef(false);
  const onReadyRef = useRef(onReady);
  /** When each request was made; a result removes its own and every older (superseded) one. */
  const requestedAtRef = useRef(new Map<number, number>());

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
          const initial = onReadyRef.current(info);
          scheduler.request(initial, initialVolumes?.current);
        }
      },
      onResult: (result) => {
        const frame =
          !hadResultRef.current ||
          (frameFromIdRef.current > 0 && result.id >= frameFromIdRef.current);
        if (frame) frameFromIdRef.current = 0;
        hadResultRef.current = true;
        const requestedAt = requestedAtRef.current.get(result.id);
        for (const id of requestedAtRef.current.keys()) {
          if (id <= result.id) requestedAtRef.current.delete(id); // this one and the superseded
        }
        viewer.current?.setTree(result, frame);
        const built = performance.now();
        // The upload and draw happen on the next animation frame (never a synchronous draw
        // here: that would block the main thread while a slider is dragged).
        const drawMs = null;
        const roundTripMs = requestedAt === undefined ? null : built - requestedAt;
        const { vertices, triangles, hash, total_ms, stems } = result.meta;
        setStats({ vertices, triangles, hash, total_ms, stems, roundTripMs, drawMs });
        setError(null);
      },
      onError: (err) => setError(err),
      onBusyChange: setBusy,
      onProgress: (fraction) => setProgress(fraction),
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
  }, [viewer, initialVolumes]);

  const request = useCallback((params: Params, frame: boolean, volumes?: VolumePrimitive[]) => {
    const scheduler = schedulerRef.current;
    if (!scheduler) return;
    const id = scheduler.request(params, volumes);
    requestedAtRef.current.set(id, performance.now());
    if (frame) frameFromIdRef.current = id;
  }, []);

  const clearError = useCallback(() => setError(null), []);

  const cancel = useCallback(() => {
    schedulerRef.current?.cancel();
  }, []);

  return { stats, error, busy, restarts, request, clearError, progress, cancel };
}
