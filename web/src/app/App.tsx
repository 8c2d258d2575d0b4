/**
 * Sylva app shell: viewer, parameter panel, stats, busy state, errors, URL persistence and
 * undo/redo of parameter changes.
 */
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { applyPreset, defaultParams, firstStage, matchingPreset, randomSeed } from '../core/params';
import type { Params, VolumePrimitive } from '../core/types';
import { Toolbar } from '../export/Toolbar';
import { ErrorBanner } from '../ui/ErrorBanner';
import { LeafInspector } from '../ui/LeafInspector';
import { GrowthProgress, GrowthTools } from '../ui/GrowthTools';
import { ParamPanel } from '../ui/ParamPanel';
import { LodPanel } from '../lod/LodPanel';
import { StatsOverlay } from '../ui/StatsOverlay';
import { Viewport } from '../ui/Viewport';
import { WindControls } from '../ui/WindControls';
import type { TreeViewer } from '../viewer/TreeViewer';
import type { ReadyInfo } from '../worker/protocol';
import { lookFrom } from '../viewer/cameraView';
import { emitDebug, installDebugHook } from './debugHook';
import { historyShortcut, ParamsHistory } from './history';
import { browserStorage, loadInitialParams, ParamsSync } from './persistence';
import { useGenerator } from './useGenerator';
import { useGrowthEditor, volumesFromUrl } from './useGrowthEditor';

/** The whole application. */
export function App() {
  const viewerRef = useRef<TreeViewer | null>(null);
  const syncRef = useRef<ParamsSync | null>(null);
  const [info, setInfo] = useState<ReadyInfo | null>(null);
  const [params, setParams] = useState<Params | null>(null);
  const [notices, setNotices] = useState<string[]>([]);
  const paramsRef = useRef<Params | null>(null);
  const historyRef = useRef<ParamsHistory | null>(null);
  const [canUndo, setCanUndo] = useState(false);
  const [canRedo, setCanRedo] = useState(false);
  // Side panel: the tree parameters or the leaf inspector.
  const [tab, setTab] = useState<'tree' | 'leaf'>('tree');

  // Growth editor: the user's volume primitives (from the URL's `vol=`), sent with every request.
  const [volumesInUrl] = useState(volumesFromUrl);
  const growthVolumesRef = useRef<VolumePrimitive[]>(volumesInUrl.volumes);
  const growthMessages = volumesInUrl.messages;

  const onReady = useCallback(
    (ready: ReadyInfo): Params => {
      const initial = loadInitialParams(ready.registry, window.location.search, browserStorage());
      paramsRef.current = initial.params;
      historyRef.current = new ParamsHistory(initial.params);
      setInfo(ready);
      setParams(initial.params);
      setNotices([...initial.messages, ...growthMessages]);
      syncRef.current ??= new ParamsSync(browserStorage());
      syncRef.current.schedule(ready.registry, initial.params);
      return initial.params;
    },
    [growthMessages],
  );

  const generator = useGenerator(viewerRef, onReady, growthVolumesRef);
  // The latest generator, for callbacks that must stay stable across renders (memoised controls).
  const generatorRef = useRef(generator);
  useEffect(() => {
    generatorRef.current = generator;
  });
  // A gizmo drag regrows the current params with the edited volumes.
  const regrow = useCallback((volumes: VolumePrimitive[]) => {
    const current = paramsRef.current;
    if (current) generatorRef.current.request(current, false, volumes);
  }, []);
  const growth = useGrowthEditor(viewerRef, params, growthVolumesRef, volumesInUrl.volumes, regrow);

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
        view: (from, to) => {
          const host = viewerRef.current?.overlayHost();
          if (host) lookFrom(host, from, to);
        },
      }),
    [],
  );

  // Show Preview is a viewer-only parameter: it toggles the envelope wireframe.
  useEffect(() => {
    viewerRef.current?.setPreviewVisible(params?.show_preview === 1);
  }, [params]);

  const registry = useMemo(() => info?.registry ?? [], [info]);
  const presets = useMemo(() => info?.presets ?? [], [info]);

  /**
   * Shows params: generation request (none when only viewer parameters changed; `interactive`
   * while a slider is dragged), state and debounced URL/storage save. The request goes out
   * first, so the worker runs while React renders.
   */
  const show = useCallback(
    (next: Params, frame: boolean, interactive = false) => {
      const previous = paramsRef.current;
      paramsRef.current = next;
      const stage = previous ? firstStage(registry, previous, next) : 'skeleton';
      if (stage !== 'viewer' && (stage !== null || frame)) {
        generatorRef.current.request(next, frame, growthVolumesRef.current, interactive);
      } else if (stage === 'viewer') {
        // Nothing to regenerate: the viewer shows or hides what it already has.
        viewerRef.current?.setPreviewVisible(next.show_preview === 1);
        emitDebug('applied', { kind: 'viewer', at: performance.now(), preview: false });
      }
      setParams(next);
      syncRef.current?.schedule(registry, next);
    },
    [registry, growthVolumesRef],
  );

  const updateHistoryState = useCallback(() => {
    setCanUndo(historyRef.current?.canUndo ?? false);
    setCanRedo(historyRef.current?.canRedo ?? false);
  }, []);

  /**
   * Applies a change and records it for undo: `key` is the param a continuous edit changes
   * (a slider drag coalesces into one step), null for a discrete step (preset, Reset, Randomize).
   */
  const apply = useCallback(
    (next: Params, key: string | null, frame: boolean, interactive = false) => {
      historyRef.current?.record(next, { key, frame, now: performance.now() });
      show(next, frame, interactive);
      updateHistoryState();
    },
    [show, updateHistoryState],
  );

  const travel = useCallback(
    (direction: 'undo' | 'redo') => {
      const history = historyRef.current;
      const entry = direction === 'undo' ? history?.undo() : history?.redo();
      if (!entry) return;
      show(entry.params, entry.frame);
      updateHistoryState();
    },
    [show, updateHistoryState],
  );
  const undo = useCallback(() => travel('undo'), [travel]);
  const redo = useCallback(() => travel('redo'), [travel]);

  // Ctrl+Z / Ctrl+Shift+Z / Ctrl+Y (⌘ on macOS), wherever the focus is: the number fields commit
  // every valid keystroke, so parameter undo also covers typing.
  useEffect(() => {
    const onKeyDown = (event: KeyboardEvent) => {
      const action = historyShortcut(event);
      if (action === null || historyRef.current === null) return;
      event.preventDefault();
      travel(action);
    };
    window.addEventListener('keydown', onKeyDown);
    return () => window.removeEventListener('keydown', onKeyDown);
  }, [travel]);

  /** A control changed a value; `interactive` while it is dragged or typed into. */
  const onChange = useCallback(
    (id: string, value: number, interactive = false) => {
      const current = paramsRef.current;
      if (current) apply({ ...current, [id]: value }, id, false, interactive);
    },
    [apply],
  );

  // A drag or a burst of typing ends when the pointer or key is released anywhere: the full
  // tree follows the preview right away (the scheduler also settles after a short pause).
  useEffect(() => {
    const settle = () => generatorRef.current.settle();
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
  }, []);

  const onChangeMany = useCallback(
    (values: Params) => {
      const current = paramsRef.current;
      if (current) apply({ ...current, ...values }, null, false);
    },
    [apply],
  );

  const activePreset = useMemo(
    () => (params ? (matchingPreset(registry, presets, params)?.name ?? null) : null),
    [registry, presets, params],
  );

  const dismiss = useCallback(() => {
    setNotices([]);
    generator.clearError();
  }, [generator]);

  const seedSpec = registry.find((s) => s.id === 'seed');

  return (
    <div className="app">
      <main className="stage">
        <Viewport viewerRef={viewerRef} />
        <LodPanel
          viewerRef={viewerRef}
          paramsRef={paramsRef}
          volumesRef={growthVolumesRef}
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
              volumesRef={growthVolumesRef}
              onLoadParams={(next) => apply(next, null, true)}
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
      {/* The tabs and the panel take their place from the start: the stage (and the canvas)
          keeps its size when the generator is ready, instead of a resize that waits for the
          GPU's first frames. */}
      <nav className="panel-tabs" aria-label="Panels">
        <button
          type="button"
          data-testid="tab-tree"
          aria-pressed={tab === 'tree'}
          disabled={!(info && params)}
          onClick={() => setTab('tree')}
        >
          Tree
        </button>
        <button
          type="button"
          data-testid="tab-leaf"
          aria-pressed={tab === 'leaf'}
          disabled={!(info && params)}
          onClick={() => setTab('leaf')}
        >
          Leaf
        </button>
      </nav>
      {info && params ? null : <aside className="panel" aria-busy="true" aria-label="Loading" />}
      {info && params && tab === 'leaf' ? (
        <LeafInspector
          registry={registry}
          params={params}
          onChange={onChange}
          onChangeMany={onChangeMany}
        />
      ) : null}
      {info && params && tab === 'tree' ? (
        <ParamPanel
          registry={registry}
          presets={presets}
          params={params}
          activePreset={activePreset}
          version={info.version}
          canUndo={canUndo}
          canRedo={canRedo}
          onChange={onChange}
          onPreset={(name) => {
            const preset = presets.find((p) => p.name === name);
            if (preset) apply(applyPreset(registry, preset), null, true);
          }}
          onRandomize={() => {
            if (seedSpec) {
              const current = paramsRef.current ?? params;
              apply({ ...current, [seedSpec.id]: randomSeed(seedSpec) }, null, false);
            }
          }}
          onReset={() => apply(defaultParams(registry), null, true)}
          onUndo={undo}
          onRedo={redo}
          extras={{
            'Growth Volume': (
              <GrowthTools
                editor={growth}
                onAdded={(group) => {
                  const current = paramsRef.current;
                  if (!current) return;
                  const next = { ...current, growth_mode: 1, show_volumes: 1 };
                  apply(group === 'crown' ? { ...next, crown_volume: 2 } : next, null, false);
                }}
              />
            ),
          }}
        />
      ) : null}
    </div>
  );
}
