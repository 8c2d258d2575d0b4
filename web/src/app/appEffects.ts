/** The app's window-wide effects: the viewer's debug hook and settling a drag on release. */
import { useEffect, type RefObject } from 'react';
import { lookFrom } from '../viewer/cameraView';
import type { TreeViewer } from '../viewer/TreeViewer';
import { installDebugHook } from './debugHook';
import type { Generator } from './useGenerator';

/** The viewer's part of `window.__sylva` (debug pages only). */
export function useViewerDebugHook(viewerRef: RefObject<TreeViewer | null>): void {
  useEffect(
    () =>
      installDebugHook({
        geometries: () => viewerRef.current?.gpuGeometries ?? null,
        programs: () => viewerRef.current?.gpuPrograms ?? null,
        pauseRendering: (paused) => {
          const viewer = viewerRef.current;
          if (viewer) viewer.rendering = !paused;
        },
        probeFrame: () => viewerRef.current?.probeFrame() ?? null,
        leafPullCheck: () => viewerRef.current?.leafPullCheck() ?? null,
        view: (from, to) => {
          const host = viewerRef.current?.overlayHost();
          if (host) lookFrom(host, from, to);
        },
      }),
    [viewerRef],
  );
}

/**
 * A drag or a burst of typing ends when the pointer or key is released anywhere: the full tree
 * follows the preview right away (the scheduler also settles after a short pause).
 */
export function useSettleOnRelease(generatorRef: RefObject<Generator | null>): void {
  useEffect(() => {
    const settle = () => generatorRef.current?.settle();
    // A range input's native `change` fires when its drag is released (React's onChange is `input`).
    const onChangeEvent = (event: Event) => {
      if (event.target instanceof HTMLInputElement && event.target.type === 'range') settle();
    };
    window.addEventListener('pointerup', settle);
    window.addEventListener('keyup', settle);
    window.addEventListener('change', onChangeEvent);
    return () => {
      window.removeEventListener('pointerup', settle);
      window.removeEventListener('keyup', settle);
      window.removeEventListener('change', onChangeEvent);
    };
  }, [generatorRef]);
}
