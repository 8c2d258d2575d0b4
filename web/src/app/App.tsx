/**
 * Sylva app shell: viewer, side panel, stats, busy state, errors and URL persistence. What the
 * user edits (params, growth volumes, undo/redo) is the editor's reducer (`useEditor`); the app
 * shows each new state: a generation request, or only a viewer change.
 */
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { matchingPreset, type Params } from 'sylva-trees/core';
import { Toolbar } from '../export/Toolbar';
import type { LodController } from '../lod/LodController';
import { LodPanel } from '../lod/LodPanel';
import { ErrorBanner } from '../ui/ErrorBanner';
import { GrowthProgress } from '../ui/GrowthTools';
import { StatsOverlay } from '../ui/StatsOverlay';
import { Viewport } from '../ui/Viewport';
import { WindControls } from '../ui/WindControls';
import type { TreeViewer } from '../viewer/TreeViewer';
import type { ReadyInfo } from 'sylva-trees/worker';
import { useSettleOnRelease, useShowState, useViewerDebugHook } from './appEffects';
import { browserStorage, loadInitialParams, ParamsSync } from './persistence';
import { SidePanel } from './SidePanel';
import { useEditor } from './useEditor';
import { useGenerator, type Generator } from './useGenerator';
import { useGrowthEditor, volumesFromUrl } from './useGrowthEditor';
import { editsFromUrl, useHandEdits } from './useHandEdits';
import { HandEditPanel } from '../ui/HandEditPanel';
import { useGenerationPool } from '../pool/useGenerationPool';

/** The whole application. */
export function App() {
  const viewerRef = useRef<TreeViewer | null>(null);
  // The LOD view's controller: the Export menu's LOD zip takes its impostor atlas.
  const lodRef = useRef<LodController | null>(null);
  const syncRef = useRef<ParamsSync | null>(null);
  const generatorRef = useRef<Generator | null>(null);
  const [info, setInfo] = useState<ReadyInfo | null>(null);
  const [notices, setNotices] = useState<string[]>([]);
  // The growth volumes (`vol=`) and hand edits (`e=`) of the share link, sent with every request.
  const [volumesInUrl] = useState(volumesFromUrl);
  const [editsInUrl] = useState(editsFromUrl);
  // The workers of the independent jobs (LOD bakes, exports, the forest's trees).
  const pool = useGenerationPool();
  const registry = useMemo(() => info?.registry ?? [], [info]);
  const presets = useMemo(() => info?.presets ?? [], [info]);

  const show = useShowState(registry, generatorRef, viewerRef, syncRef);
  const editor = useEditor(volumesInUrl.volumes, editsInUrl.edits, show);
  const { params, volumes } = editor.state;

  const { load } = editor;
  const growthMessages = useMemo(
    () => [...volumesInUrl.messages, ...editsInUrl.messages],
    [volumesInUrl, editsInUrl],
  );
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

  const { volumesRef, editsRef } = editor;
  const initialShape = useMemo(() => ({ volumesRef, editsRef }), [volumesRef, editsRef]);
  const generator = useGenerator(viewerRef, onReady, initialShape);
  useEffect(() => {
    generatorRef.current = generator;
  });
  const growth = useGrowthEditor(viewerRef, params, volumes, editor.change);
  const addNotice = useCallback((text: string) => setNotices((list) => [...list, text]), []);
  const hand = useHandEdits(viewerRef, editor, addNotice, generatorRef);
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
          lodRef={lodRef}
          paramsRef={editor.paramsRef}
          volumesRef={editor.volumesRef}
          editsRef={editor.editsRef}
          info={info}
          pool={pool}
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
              lodRef={lodRef}
              version={info.version}
              exportFormats={info.exportFormats ?? []}
              exporter={pool}
              volumesRef={editor.volumesRef}
              editsRef={editor.editsRef}
              onLoadParams={(next) => editor.change({ params: next, key: null, frame: true })}
            />
          ) : null}
          <WindControls viewerRef={viewerRef} />
        </div>
        {info && params ? <HandEditPanel hand={hand} /> : null}
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
        core={info ? { version: info.version, threads: info.threads ?? 1 } : null}
        activePreset={activePreset}
        editor={editor}
        growth={growth}
      />
    </div>
  );
}
