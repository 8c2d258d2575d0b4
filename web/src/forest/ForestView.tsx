/**
 * The forest mode: a full-stage view with its own canvas (ForestScene), a tree-count slider
 * (1,000 by default, up to 10,000) and live stats (draw calls and their bound, frame time, trees
 * per level). The forest is K unique trees (16 by default, up to 64), each its own species and
 * seed, as the recipe in the link says (`recipe.ts`: count, seed, species; `ecology.ts` picks
 * each tree's species from the species map and places them). They are generated with their
 * levels of detail in the app's generation pool (`pool/generationPool.ts`: one worker per core,
 * at most 4), apart from the editor's worker, and each appears as it finishes.
 */
import { useEffect, useRef, useState } from 'react';
import { applyPreset, type Params } from 'sylva-trees/core';
import type { ReadyInfo } from 'sylva-trees/worker';
import { installDebugHook } from '../app/debugHook';
import { withQueryEntry } from '../app/queryEntry';
import type { GenerationPool } from '../pool/generationPool';
import type { AppPool } from '../pool/useGenerationPool';
import { uniqueTrees } from './ecology';
import { ForestScene, type ForestStats } from './ForestScene';
import { decodeRecipe, encodeRecipe, type ForestRecipe } from './recipe';

/** Presets the forest mixes by default (those present are used, in this order). */
export const FOREST_PRESETS = ['quaking_aspen', 'fir', 'oak', 'cypress'];
/** Default and largest number of trees. */
export const DEFAULT_TREES = 1000;
export const MAX_TREES = 10_000;
/** The share link's entry holding the forest's recipe (`recipe.ts`). */
export const FOREST_ENTRY = 'forest';

const integer = new Intl.NumberFormat('en-US');

/** The page's query at load (the app rewrites the URL with its own params soon after). */
const INITIAL_SEARCH = typeof window === 'undefined' ? '' : window.location.search;

/** Whether the page was opened with a forest link (the forest view then opens at once). */
export function openedWithForest(): boolean {
  return new URLSearchParams(INITIAL_SEARCH).has(FOREST_ENTRY);
}

/** The recipe of the link the page was opened with (the defaults without one), and its notices. */
export function initialRecipe(info: ReadyInfo): { recipe: ForestRecipe; notices: string[] } {
  const names = info.presets.map((p) => p.name);
  return decodeRecipe(new URLSearchParams(INITIAL_SEARCH).get(FOREST_ENTRY), names, FOREST_PRESETS);
}

/**
 * The parameters of each unique tree of `recipe`: its species' preset with its own seed, in the
 * editor's `season` when one is given (the forest is in the month the studio shows).
 */
export function uniqueParams(
  info: ReadyInfo,
  recipe: ForestRecipe,
  season?: number,
): { params: Params; species: number }[] {
  return uniqueTrees(recipe.count, recipe.species.length, recipe.seed).flatMap((tree) => {
    const preset = info.presets.find((p) => p.name === recipe.species[tree.species]);
    if (!preset) return [];
    const params: Params = { ...applyPreset(info.registry, preset), seed: tree.seed };
    if (season !== undefined) params.season = season;
    return [{ params, species: tree.species }];
  });
}

/** Writes the recipe into the page's link (removed with null), leaving the other entries as they are. */
function writeRecipe(recipe: ForestRecipe | null): void {
  const search = withQueryEntry(
    window.location.search,
    FOREST_ENTRY,
    recipe ? encodeRecipe(recipe) : '',
  );
  window.history.replaceState(
    window.history.state,
    '',
    `${window.location.pathname}${search}${window.location.hash}`,
  );
}

/**
 * Generates every unique tree in the pool (as many at once as it has workers, with the leaves
 * baked in the worker: the forest draws them as one mesh) and adds each to `scene` as it comes,
 * so trees appear as they finish. Returns a function that takes the trees still waiting out of
 * the pool's queue and ignores the few being generated (they finish in their workers).
 */
function loadTrees(
  pool: GenerationPool,
  all: { params: Params; species: number }[],
  scene: ForestScene,
  on: { shown: (at: number) => void; failed: (message: string) => void },
): () => void {
  let cancelled = false;
  scene.setArriving(all.length > 0);
  const waiting = new AbortController();
  const runs = all.map(({ params, species }, id) =>
    pool.lods(params, undefined, undefined, { bakeLeaves: true, signal: waiting.signal }).then(
      (lods) => {
        if (cancelled) return;
        scene.enqueue(lods, { id, species }, () => {
          if (!cancelled) on.shown(performance.now());
        });
      },
      (e: unknown) => {
        if (cancelled) return;
        on.failed(e instanceof Error ? e.message : String(e));
      },
    ),
  );
  // Every tree in (or failed): frames at full pace and resolution again.
  void Promise.all(runs).then(() => {
    if (!cancelled) scene.setArriving(false);
  });
  return () => {
    cancelled = true;
    waiting.abort();
  };
}

/** The forest's part of the debug hook; `setCount` follows a count set through it. */
function installForestHook(
  scene: ForestScene,
  expectedVarieties: number,
  pool: { size: number; openedAt: number; shownAt: number[] },
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
        openedAt: pool.openedAt,
        shownAt: [...pool.shownAt],
        poolSize: pool.size,
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
export function ForestView({
  info,
  season,
  pool,
}: {
  info: ReadyInfo;
  season?: number;
  /** The app's generation pool (shared with the LOD panel and the exports). */
  pool: AppPool;
}) {
  const containerRef = useRef<HTMLDivElement>(null);
  const sceneRef = useRef<ForestScene | null>(null);
  const [count, setCount] = useState(DEFAULT_TREES);
  const countRef = useRef(count);
  const [stats, setStats] = useState<ForestStats | null>(null);
  const [loaded, setLoaded] = useState(0);
  const [total, setTotal] = useState(0);
  // What was wrong with the link's recipe, if anything (the defaults stand in).
  const [error, setError] = useState<string | null>(() => {
    const { notices } = initialRecipe(info);
    return notices.length > 0 ? notices.join('; ') : null;
  });

  useEffect(() => {
    const container = containerRef.current;
    if (!container) return;
    const scene = new ForestScene(container);
    sceneRef.current = scene;
    const { recipe } = initialRecipe(info);
    scene.setCount(countRef.current, recipe.seed, recipe.species.length);
    writeRecipe(recipe);
    const generation = pool.get();
    const all = uniqueParams(info, recipe, season);
    setTotal(all.length);
    const timing = { size: generation.size, openedAt: performance.now(), shownAt: [] as number[] };
    const stop = loadTrees(generation, all, scene, {
      shown: (at) => {
        timing.shownAt.push(at);
        setLoaded(scene.varietyCount);
      },
      failed: setError,
    });
    const timer = window.setInterval(() => setStats(scene.stats()), 500);
    const uninstall = installForestHook(scene, all.length, timing, (n) => {
      countRef.current = n;
      setCount(n);
    });
    return () => {
      stop();
      uninstall();
      window.clearInterval(timer);
      scene.dispose();
      sceneRef.current = null;
      writeRecipe(null);
    };
  }, [info, season, pool]);

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
          <dt>Unique trees</dt>
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
