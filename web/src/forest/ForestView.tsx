/**
 * The forest mode: a full-stage view with its own canvas (ForestScene), a tree-count slider
 * (1,000 by default, up to 10,000) and live stats (draw calls and their bound, frame time, trees
 * per level). The varieties (a few presets × 2 seeds) are generated with their levels of detail
 * in a worker of their own, one request per variety.
 */
import { useEffect, useRef, useState } from 'react';
import { applyPreset, type Params } from 'sylva-trees/core';
import { createModuleWorker } from '../createWorker';
import { installDebugHook } from '../app/debugHook';
import { LodClient } from '../lod/lodClient';
import type { ReadyInfo } from 'sylva-trees/worker';
import { ForestScene, type ForestStats } from './ForestScene';

/** Presets the forest mixes (those present are used, in this order). */
export const FOREST_PRESETS = ['quaking_aspen', 'fir', 'oak', 'cypress'];
/** Seeds per preset. */
export const FOREST_SEEDS = [1, 2];
/** Default and largest number of trees. */
export const DEFAULT_TREES = 1000;
export const MAX_TREES = 10_000;

const integer = new Intl.NumberFormat('en-US');

/** Parameters of each variety: preset × seed. */
export function varietyParams(
  info: ReadyInfo,
  presets = FOREST_PRESETS,
  seeds = FOREST_SEEDS,
): Params[] {
  const chosen = presets
    .map((name) => info.presets.find((p) => p.name === name))
    .filter((p) => p !== undefined);
  const list = chosen.length > 0 ? chosen : info.presets.slice(0, 1);
  return list.flatMap((preset) =>
    seeds.map((seed) => ({ ...applyPreset(info.registry, preset), seed })),
  );
}

/** The page's query at load (the app rewrites the URL with its own params soon after). */
const INITIAL_SEARCH = typeof window === 'undefined' ? '' : window.location.search;

/** Reads `?forestVarieties=k` from the URL the page was opened with (tests use fewer). */
function varietyLimit(): number {
  const k = Number(new URLSearchParams(INITIAL_SEARCH).get('forestVarieties'));
  return Number.isInteger(k) && k > 0 ? k : Infinity;
}

/**
 * Generates `all` varieties in turn and adds each to `scene` as it comes; the scene stops
 * showing its loading state when every one has settled. Returns a function that ignores what
 * is still to come.
 */
function loadVarieties(
  client: LodClient,
  all: Params[],
  scene: ForestScene,
  on: { loaded: () => void; failed: (message: string) => void },
): () => void {
  let cancelled = false;
  let settled = 0;
  const settle = () => {
    settled++;
    if (settled === all.length) scene.setLoading(false);
  };
  for (const params of all) {
    client.request(params).then(
      (lods) => {
        if (cancelled) return;
        scene.addVariety(lods);
        on.loaded();
        settle();
      },
      (e: unknown) => {
        if (cancelled) return;
        on.failed(e instanceof Error ? e.message : String(e));
        settle();
      },
    );
  }
  return () => {
    cancelled = true;
  };
}

/** The forest's part of the debug hook; `setCount` follows a count set through it. */
function installForestHook(
  scene: ForestScene,
  expectedVarieties: number,
  setCount: (n: number) => void,
): () => void {
  return installDebugHook({
    forest: () => {
      const s = scene.stats();
      return {
        drawCalls: s.drawCalls,
        bound: s.bound,
        instances: s.trees,
        visible: s.visible,
        perLevel: s.perLevel,
        frameMs: s.frameMs,
        cpuMs: s.cpuMs,
        assignMs: s.assignMs,
        varieties: s.varieties,
        expectedVarieties,
        bakeMs: scene.bakeMs,
      };
    },
    setForestTrees: (n: number) => {
      setCount(n);
      scene.setCount(n);
    },
    setForestCameraDistance: (d: number) => scene.setCameraDistance(d),
  });
}

/** See the module docs. */
export function ForestView({ info }: { info: ReadyInfo }) {
  const containerRef = useRef<HTMLDivElement>(null);
  const sceneRef = useRef<ForestScene | null>(null);
  const [count, setCount] = useState(DEFAULT_TREES);
  const countRef = useRef(count);
  const [stats, setStats] = useState<ForestStats | null>(null);
  const [loaded, setLoaded] = useState(0);
  const [total, setTotal] = useState(0);
  const [error, setError] = useState<string | null>(null);

  useEffect(() => {
    const container = containerRef.current;
    if (!container) return;
    const scene = new ForestScene(container);
    sceneRef.current = scene;
    scene.setCount(countRef.current);
    // Queued, and with the leaves baked in the worker (the forest draws them as one mesh).
    const client = new LodClient(createModuleWorker, false, true);
    const all = varietyParams(info).slice(0, varietyLimit());
    setTotal(all.length);
    const stop = loadVarieties(client, all, scene, {
      loaded: () => setLoaded(scene.varietyCount),
      failed: setError,
    });
    const timer = window.setInterval(() => setStats(scene.stats()), 500);
    const uninstall = installForestHook(scene, all.length, (n) => {
      countRef.current = n;
      setCount(n);
    });
    return () => {
      stop();
      uninstall();
      window.clearInterval(timer);
      client.dispose();
      scene.dispose();
      sceneRef.current = null;
    };
  }, [info]);

  const onCount = (n: number) => {
    countRef.current = n;
    setCount(n);
    sceneRef.current?.setCount(n);
  };

  return (
    <div className="forest" data-testid="forest-view">
      <div className="forest-canvas" ref={containerRef} />
      <div className="forest-stats" aria-live="polite">
        <label className="forest-count">
          Trees <strong data-testid="forest-count">{integer.format(count)}</strong>
          <input
            type="range"
            min={100}
            max={MAX_TREES}
            step={100}
            value={count}
            data-testid="forest-slider"
            onChange={(e) => onCount(Number(e.target.value))}
          />
        </label>
        <dl>
          <dt>Varieties</dt>
          <dd data-testid="forest-varieties" data-loaded={loaded} data-total={total}>
            {loaded < total ? `${loaded} / ${total} (generating…)` : loaded}
          </dd>
          <dt>Draw calls</dt>
          <dd
            data-testid="forest-draw-calls"
            data-draw-calls={stats?.drawCalls ?? ''}
            data-bound={stats?.bound ?? ''}
          >
            {stats ? `${stats.drawCalls} (≤ ${stats.bound})` : '–'}
          </dd>
          <dt>Frame time</dt>
          <dd data-testid="forest-frame-ms" data-frame-ms={stats?.frameMs ?? ''}>
            {stats ? `${stats.frameMs.toFixed(1)} ms (CPU ${stats.cpuMs.toFixed(1)})` : '–'}
          </dd>
          <dt>Per level</dt>
          <dd data-testid="forest-per-level" data-per-level={stats?.perLevel.join(',') ?? ''}>
            {stats ? stats.perLevel.map((n) => integer.format(n)).join(' / ') : '–'}
          </dd>
          <dt>Triangles</dt>
          <dd data-testid="forest-triangles">{stats ? integer.format(stats.triangles) : '–'}</dd>
        </dl>
        {error ? (
          <div className="forest-error" role="alert">
            {error}
          </div>
        ) : null}
      </div>
    </div>
  );
}
