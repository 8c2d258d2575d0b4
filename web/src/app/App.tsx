/**
 * Sylva app shell: viewer, side panel, stats, busy state, errors and URL persistence. What the
 * user edits (params, growth volumes, undo/redo) is the editor's reducer (`useEditor`); the app
 * shows each new state: a generation request, or only a viewer change.
 */
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { firstStage, matchingPreset, type Params } from 'sylva-trees/core';
import { Toolbar } from '../export/Toolbar';
import { LodPanel } from '../lod/LodPanel';
import { ErrorBanner } from '../ui/ErrorBanner';
import { GrowthProgress } from '../ui/GrowthTools';
import { StatsOverlay } from '../ui/StatsOverlay';
import { Viewport } from '../ui/Viewport';
import { WindControls } from '../ui/WindControls';
import type { TreeViewer } from '../viewer/TreeViewer';
import type { ReadyInfo } from 'sylva-trees/worker';
import { useSettleOnRelease, useViewerDebugHook } from './appEffects';
import { emitDebug } from './debugHook';
import type { EditorState } from './editor';
import { browserStorage, loadInitialParams, ParamsSync } from './persistence';
import { SidePanel } from './SidePanel';
import { useEditor } from './useEditor';
import { useGenerator, type Generator } from './useGenerator';
import { useGrowthEditor, volumesFromUrl } from './useGrowthEditor';

/** The whole application. */
export function App() {
  const viewerRef = useRef<TreeViewer | null>(null);
  const syncRef = useRef<ParamsSync | null>(null);
  const generatorRef = useRef<Generator | null>(null);
  const [info, setInfo] = useState<ReadyInfo | null>(null);
  const [notices, setNotices] = useState<string[]>([]);
  // The growth volumes of the share link (`vol=`), sent with every request.
  const [volumesInUrl] = useState(volumesFromUrl);
  const registry = useMemo(() => info?.registry ?? [], [info]);
  const presets = useMemo(() => info?.presets ?? [], [info]);

  /**
   * Shows a new state: a generation request (none when only viewer parameters changed;
   * `interactive` while a slider is dragged), and the debounced URL/storage save. The request
   * goes out first, so the worker runs while React renders.
   */
  const show = useCallback(
    (previous: EditorState, next: EditorState, interactive: boolean) => {
      const params = next.params;
      if (params === null) return;
      const stage = previous.params ? firstStage(registry, previous.params, params) : 'skeleton';
      const regrow = next.volumes !== previous.volumes;
      if (regrow || (stage !== 'viewer' && (stage !== null || next.frame))) {
        generatorRef.current?.request(params, next.frame, next.volumes, interactive && !regrow);
      } else if (stage === 'viewer') {
        // Nothing to regenerate: the viewer shows or hides what it already has.
        viewerRef.current?.setPreviewVisible(params.show_preview === 1);
        emitDebug('applied', { kind: 'viewer', at: performance.now(), preview: false });
      }
      syncRef.current?.schedule(registry, params);
    },
    [registry],
  );
  const editor = useEditor(volumesInUrl.volumes, show);
  const { params, volumes } = editor.state;

  const { load } = editor;
  const growthMessages = volumesInUrl.messages;
  const onReady = useCallback(
    (ready: ReadyInfo): Params => {
      const initial = loadInitialParams(ready.registry, window.location.search, browserStorage());
      load(initial.params);
      setInfo(ready);
      setNotices([...initial.messages, ...growthMessages]);
      syncRef.current ??= new ParamsSync(browserStorage());
      syncRef.current.schedule(ready.registry, initial.params);
      return initial.params;
    },
    [growthMessages, load],
  );

  const generator = useGenerator(viewerRef, onReady, editor.volumesRef);
  useEffect(() => {
    generatorRef.current = generator;
  });
  const growth = useGrowthEditor(viewerRef, params, volumes, editor.change);
  useViewerDebugHook(viewerRef);
  useSettleOnRelease(generatorRef);

  // Show Preview is a viewer-only parameter: it toggles the envelope wireframe.
  useEffect(() => {
    viewerRef.current?.setPreviewVisible(params?.show_preview === 1);
  }, [params]);

  const activePreset = useMemo(
    () => (params ? (matchingPreset(registry, presets, params)?.name ?? null) : null),
    [registry, presets, params],
  );

  const dismiss = useCallback(() => {
    setNotices([]);
    generator.clearError();
  }, [generator]);

  return (
    <div className="app">
      <main className="stage">
        <Viewport viewerRef={viewerRef} />
        <LodPanel
          viewerRef={viewerRef}
          paramsRef={editor.paramsRef}
          volumesRef={editor.volumesRef}
          info={info}
        />
        {/* Stats, toolbar and wind in one row that wraps on a narrow stage: never on top of each other. */}
        <div className="stage-top">
          <StatsOverlay store={generator.stats} />
          {info && params ? (
            <Toolbar
              registry={registry}
              params={params}
              presetName={activePreset}
              viewerRef={viewerRef}
              volumesRef={editor.volumesRef}
              onLoadParams={(next) => editor.change({ params: next, key: null, frame: true })}
            />
          ) : null}
          <WindControls viewerRef={viewerRef} />
        </div>
        <GrowthProgress progress={generator.progress} onCancel={() => generator.cancel()} />
        <ErrorBanner
          error={generator.error}
          notices={notices}
          registry={registry}
          onDismiss={dismiss}
        />
        {info === null ? <div className="loading">Loading the generator…</div> : null}
      </main>
      <SidePanel
        registry={registry}
        presets={presets}
        params={info ? params : null}
        version={info?.version ?? null}
        activePreset={activePreset}
        editor={editor}
        growth={growth}
      />
    </div>
  );
}
