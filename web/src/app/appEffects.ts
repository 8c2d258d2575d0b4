/**
 * The app's effects: showing each new editor state (a generation request or a viewer change),
 * the viewer's debug hook and settling a drag on release.
 */
import { useCallback, useEffect, type RefObject } from 'react';
import { firstStage, type ParamSpec } from 'sylva-trees/core';
import { lookFrom } from '../viewer/cameraView';
import type { TreeViewer } from '../viewer/TreeViewer';
import { emitDebug, installDebugHook } from './debugHook';
import type { EditorState } from './editor';
import type { ParamsSync } from './persistence';
import type { Generator, TreeShape } from './useGenerator';

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
        organs: () => viewerRef.current?.organs() ?? null,
        endGrainKind: () => viewerRef.current?.endGrainKind ?? -1,
        setOrgansVisible: (visible) => viewerRef.current?.setOrgansVisible(visible),
        view: (from, to) => {
          const host = viewerRef.current?.overlayHost();
          if (host) lookFrom(host, from, to);
        },
        setGroundVisible: (visible) => viewerRef.current?.setGroundVisible(visible),
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

/** What showing a new state takes: a generation request, a viewer-only change, or nothing. */
export interface ShowPlan {
  request: TreeShape | null;
  viewer: boolean;
}

/**
 * Whether `next` (after `previous`) needs a tree, and the request's volumes, edits and whether
 * it is interactive. A new volume list or edit list always regenerates (the skeleton stage); a
 * drag of a volume never asks for a preview, a stroke or bend being drawn does.
 */
export function planShow(
  registry: readonly ParamSpec[],
  previous: EditorState,
  next: EditorState,
  interactive: boolean,
): ShowPlan {
  const params = next.params;
  if (params === null) return { request: null, viewer: false };
  const stage = previous.params ? firstStage(registry, previous.params, params) : 'skeleton';
  const regrow = next.volumes !== previous.volumes;
  const reshaped = next.edits !== previous.edits;
  if (regrow || reshaped || (stage !== 'viewer' && (stage !== null || next.frame))) {
    const { volumes, edits } = next;
    return { request: { volumes, edits, interactive: interactive && !regrow }, viewer: false };
  }
  return { request: null, viewer: stage === 'viewer' };
}

/** Shows `next`, the editor state after `previous`. */
export type ShowStateFn = (previous: EditorState, next: EditorState, interactive: boolean) => void;

/**
 * Shows a new state: a generation request (none when only viewer parameters changed;
 * `interactive` while a slider is dragged or a stroke drawn), and the debounced URL/storage
 * save. The request goes out first, so the worker runs while React renders. A change of the
 * growth volumes or of the edit list always regenerates (the skeleton stage).
 */
export function useShowState(
  registry: readonly ParamSpec[],
  generatorRef: RefObject<Generator | null>,
  viewerRef: RefObject<TreeViewer | null>,
  syncRef: RefObject<ParamsSync | null>,
): ShowStateFn {
  return useCallback(
    (previous: EditorState, next: EditorState, interactive: boolean) => {
      const params = next.params;
      if (params === null) return;
      const plan = planShow(registry, previous, next, interactive);
      if (plan.request) {
        generatorRef.current?.request(params, next.frame, plan.request);
      } else if (plan.viewer) {
        // Nothing to regenerate: the viewer shows or hides what it already has.
        viewerRef.current?.setPreviewVisible(params.show_preview === 1);
        emitDebug('applied', { kind: 'viewer', at: performance.now(), preview: false });
      }
      syncRef.current?.schedule(registry, params);
    },
    [registry, generatorRef, viewerRef, syncRef],
  );
}
