/**
 * The LOD control over the viewer, bottom right (Auto / LOD0 / LOD1 / LOD2 / Impostor), the triangle count of
 * each level with the one on screen highlighted, and the Forest toggle, which lays the forest view
 * over the stage (the tree viewer stays mounted underneath and keeps its tree).
 */
import { useEffect, useRef, useState, type RefObject } from 'react';
import { installDebugHook } from '../app/debugHook';
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';
import { ForestView, openedWithForest } from '../forest/ForestView';
import type { TreeViewer } from '../viewer/TreeViewer';
import type { ReadyInfo } from 'sylva-trees/worker';
import type { AppPool } from '../pool/useGenerationPool';
import { LodClient } from './lodClient';
import { LodController, type LodMode, type LodState } from './LodController';
import { LEVEL_NAMES } from './selection';
import './lod.css';

const integer = new Intl.NumberFormat('en-US');
const MODES: { mode: LodMode; label: string }[] = [
  { mode: 'auto', label: 'Auto' },
  { mode: 0, label: '0' },
  { mode: 1, label: '1' },
  { mode: 2, label: '2' },
  { mode: 3, label: 'Imp' },
];

/** See the module docs. */
export function LodPanel({
  viewerRef,
  lodRef,
  paramsRef,
  volumesRef,
  editsRef,
  info,
  pool,
}: {
  viewerRef: RefObject<TreeViewer | null>;
  /** Set to the controller while the panel is mounted (the LOD export takes its impostor). */
  lodRef: RefObject<LodController | null>;
  paramsRef: RefObject<Params | null>;
  volumesRef: RefObject<VolumePrimitive[]>;
  editsRef: RefObject<Edit[]>;
  info: ReadyInfo | null;
  /** The app's generation pool: the levels and the forest's trees are made there. */
  pool: AppPool;
}) {
  const controllerRef = useRef<LodController | null>(null);
  const [state, setState] = useState<LodState | null>(null);
  // A forest link (`?forest=…`) opens the forest view at once.
  const [forest, setForest] = useState(openedWithForest);
  // The forest is in the month the studio shows when it opens (Season).
  const [forestSeason, setForestSeason] = useState<number | undefined>(undefined);

  useEffect(() => {
    const viewer = viewerRef.current;
    if (!viewer) return;
    const client = new LodClient(pool.get());
    const controller = new LodController(
      viewer.overlayHost(),
      client,
      {
        params: () => paramsRef.current,
        volumes: () => volumesRef.current,
        edits: () => editsRef.current,
      },
      setState,
    );
    controllerRef.current = controller;
    lodRef.current = controller;
    const uninstall = installDebugHook({
      lod: () => controller.state(),
      setCameraDistance: (d: number) => controller.setCameraDistance(d),
      setLodMode: (mode: LodMode) => controller.setMode(mode),
    });
    return () => {
      uninstall();
      controller.dispose();
      client.dispose();
      controllerRef.current = null;
      if (lodRef.current === controller) lodRef.current = null;
    };
  }, [viewerRef, lodRef, paramsRef, volumesRef, editsRef, pool]);

  const mode = state?.mode ?? 'auto';
  const level = state?.level ?? 0;
  return (
    <>
      {forest && info ? <ForestView info={info} season={forestSeason} pool={pool} /> : null}
      <div className="lod-panel" data-testid="lod-panel">
        <div className="lod-row">
          <span className="lod-title">LOD</span>
          <div className="lod-modes" role="group" aria-label="Level of detail">
            {MODES.map(({ mode: m, label }) => (
              <button
                key={String(m)}
                type="button"
                data-testid={`lod-mode-${m}`}
                aria-pressed={mode === m}
                disabled={forest}
                onClick={() => controllerRef.current?.setMode(m)}
              >
                {label}
              </button>
            ))}
          </div>
          <button
            type="button"
            className="lod-forest"
            data-testid="forest-toggle"
            aria-pressed={forest}
            disabled={!info}
            onClick={() => {
              const season = paramsRef.current?.season;
              setForestSeason(typeof season === 'number' ? season : undefined);
              setForest((f) => !f);
            }}
          >
            Forest
          </button>
        </div>
        {forest ? null : (
          <dl
            className="lod-levels"
            data-testid="lod-levels"
            data-level={level}
            data-ready={state?.ready ? 'true' : 'false'}
            data-screen={state ? state.screen.toFixed(3) : ''}
          >
            {LEVEL_NAMES.map((name, l) => (
              <div key={name} className={l === level ? 'lod-current' : undefined}>
                <dt>{name}</dt>
                <dd data-testid={`lod-triangles-${l}`} data-triangles={state?.triangles?.[l] ?? ''}>
                  {state?.triangles ? `${integer.format(state.triangles[l] ?? 0)} tris` : '…'}
                </dd>
              </div>
            ))}
          </dl>
        )}
      </div>
    </>
  );
}
