/** Sylva app shell: viewer, parameter panel, stats, busy state, errors and URL persistence. */
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { applyPreset, defaultParams, matchingPreset, randomSeed } from '../core/params';
import type { Params } from '../core/types';
import { ErrorBanner } from '../ui/ErrorBanner';
import { ParamPanel } from '../ui/ParamPanel';
import { StatsOverlay } from '../ui/StatsOverlay';
import { Viewport } from '../ui/Viewport';
import type { TreeViewer } from '../viewer/TreeViewer';
import type { ReadyInfo } from '../worker/protocol';
import { browserStorage, loadInitialParams, ParamsSync } from './persistence';
import { useGenerator } from './useGenerator';

/** The whole application. */
export function App() {
  const viewerRef = useRef<TreeViewer | null>(null);
  const syncRef = useRef<ParamsSync | null>(null);
  const [info, setInfo] = useState<ReadyInfo | null>(null);
  const [params, setParams] = useState<Params | null>(null);
  const [notices, setNotices] = useState<string[]>([]);
  const paramsRef = useRef<Params | null>(null);

  const onReady = useCallback((ready: ReadyInfo): Params => {
    const initial = loadInitialParams(ready.registry, window.location.search, browserStorage());
    paramsRef.current = initial.params;
    setInfo(ready);
    setParams(initial.params);
    setNotices(initial.messages);
    syncRef.current ??= new ParamsSync(browserStorage());
    syncRef.current.schedule(ready.registry, initial.params);
    return initial.params;
  }, []);

  const generator = useGenerator(viewerRef, onReady);

  // Show Preview is a viewer-only parameter: it toggles the envelope wireframe.
  useEffect(() => {
    viewerRef.current?.setPreviewVisible(params?.show_preview === 1);
  }, [params]);

  const registry = useMemo(() => info?.registry ?? [], [info]);
  const presets = useMemo(() => info?.presets ?? [], [info]);

  /** Applies new params: state, generation request and debounced URL/storage save. */
  const apply = useCallback(
    (next: Params, frame = false) => {
      paramsRef.current = next;
      setParams(next);
      generator.request(next, frame);
      syncRef.current?.schedule(registry, next);
    },
    [generator, registry],
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
        <StatsOverlay stats={generator.stats} busy={generator.busy} />
        <ErrorBanner
          error={generator.error}
          notices={notices}
          registry={registry}
          onDismiss={dismiss}
        />
        {info === null ? <div className="loading">Loading the generator…</div> : null}
      </main>
      {info && params ? (
        <ParamPanel
          registry={registry}
          presets={presets}
          params={params}
          activePreset={activePreset}
          version={info.version}
          onChange={(id, value) => apply({ ...(paramsRef.current ?? params), [id]: value })}
          onPreset={(name) => {
            const preset = presets.find((p) => p.name === name);
            if (preset) apply(applyPreset(registry, preset), true);
          }}
          onRandomize={() => {
            if (seedSpec) {
              apply({ ...(paramsRef.current ?? params), [seedSpec.id]: randomSeed(seedSpec) });
            }
          }}
          onReset={() => apply(defaultParams(registry), true)}
        />
      ) : null}
    </div>
  );
}
