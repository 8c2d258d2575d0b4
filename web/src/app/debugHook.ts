/** The `window.__sylva` debug hook (dev mode or `?debug=1` only). */
import type { LeafPullCheck } from '../viewer/leafPullCheck';
import type { OrganDebug } from '../viewer/TreeViewer';
import type { ForestDebug } from '../forest/ForestScene';
import type { LodMode, LodState } from '../lod/LodController';
import type { PoolState } from '../pool/generationPool';
import type { WindSettings } from 'sylva-trees/viewer';

/** A tree the viewer applied (the debug hook's log; benchmarks time answers with it). */
export interface TreeApplied {
  /** Request id. */
  id: number;
  /** `performance.now()` when its arrays were in the scene, ready for the next frame. */
  at: number;
  /** When it was requested (null for a request made before the log). */
  requestedAt: number | null;
  /** A preview (a drag's quick answer). */
  preview: boolean;
}

/** What the debug hook exposes to tests and the console. */
export interface SylvaDebugHook {
  /** Makes the generator worker panic (tests the crash-recovery path; the debug build only). */
  panic(): void;
  /** Makes the generator worker busy-loop for `ms` (tests the time limit; the debug build only). */
  hang(ms: number): void;
  /** The trees applied so far (the last 200), oldest first. */
  trees(): TreeApplied[];
  /** Benchmarks: stops (true) or resumes drawing frames; trees are still applied. */
  pauseRendering(paused: boolean): void;
  /** Benchmarks: draws a frame now, waits for the GPU, returns its upload + draw time (ms). */
  probeFrame(): number | null;
  /**
   * Whether a drag settles after 150 ms without input (default) or only on release: the drag
   * benchmark waits for each software-WebGL frame, longer than that pause.
   */
  settleWhenIdle(on: boolean): void;
  /** Sets the generation time limit in ms (tests use a short one). */
  setTimeLimit(ms: number): void;
  /** Geometries alive on the GPU (three.js `renderer.info.memory.geometries`), for leak tests. */
  geometries(): number | null;
  /** Shader programs compiled so far, for jank tests. */
  programs(): number | null;
  /** Puts the camera at `from` looking at `to` (metres, Y up), e.g. for close-up screenshots. */
  view(from: [number, number, number], to: [number, number, number]): void;
  /** Shows or hides the viewer's ground disc (brightness tests: the tree alone, no shadow). */
  setGroundVisible(visible: boolean): void;
  /** Growth overlay: markers and primitive wireframes drawn now, and whether a gizmo drag runs. */
  growth(): { markers: number; volumes: number; dragging: boolean };
  /**
   * Hand edits: the active tool, whether it drags, how many edits the list holds, and the
   * bounds of the tree shown (tree space, from its meta; null before the first tree).
   */
  edits(): {
    tool: string | null;
    dragging: boolean;
    /** Brush points of the paint stroke being drawn (0 without one). */
    strokePoints: number;
    count: number;
    bounds: { min: number[]; max: number[] } | null;
  };
  /** The bark point under client pixel `(x, y)` (tree space), or null (e2e: find a branch). */
  pickBark(x: number, y: number): [number, number, number] | null;
  /** Client pixel of tree-space point `p` (e2e: aim the mouse). */
  project(p: [number, number, number]): [number, number];
  /** Levels of detail: level on screen (3 = impostor), triangles per level, screen size. */
  lod(): LodState;
  /** Moves the viewer's camera to `distance` m from the orbit target (LOD tests). */
  setCameraDistance(distance: number): void;
  /** LOD mode: 'auto' or a forced level 0..3. */
  setLodMode(mode: LodMode): void;
  /** The generation pool (LOD bakes, exports, the forest's trees): workers started, jobs. */
  pool(): PoolState;
  /** Forest view (while open): draw calls and their bound, trees, frame time, trees per level. */
  forest(): ForestDebug;
  /** Forest view: sets the number of trees. */
  setForestTrees(n: number): void;
  /** Forest view: moves the camera to `distance` m from its target. */
  setForestCameraDistance(distance: number): void;
  /** Wind: sets the shader time (seconds); the next frame shows that moment. */
  setWindTime(seconds: number): void;
  /** Wind: changes settings (on/off, strength, direction, gust, pause), as the controls do. */
  setWind(settings: Partial<WindSettings>): void;
  /** Wind: stops (true) or restarts the clock. */
  pauseWind(paused: boolean): void;
  /** Wind: current settings, shader time and whether the bark has the core's per-vertex data. */
  wind(): WindSettings & { time: number; vertexData: boolean };
  /** Renders one frame now and returns a hash of the canvas pixels (`WxH:hash`). */
  frameHash(): string | null;
  /** Leaves drawn pulled and as an InstancedMesh, compared (null before the first tree). */
  leafPullCheck(): LeafPullCheck | null;
  /** Size of the bark colour map, null before it arrived. */
  barkTexture(): { width: number; height: number } | null;
  /** The bark type of the cut faces' end grain in the viewer, -1 before the worker sent one. */
  endGrainKind(): number;
  /** Flowers, fruit, catkins and buds drawn (one InstancedMesh per set) and the fallen leaves. */
  organs(): OrganDebug | null;
  /** Shows or hides the organ meshes (e2e: a frame with and without them). */
  setOrgansVisible(visible: boolean): void;
}

declare global {
  interface Window {
    __sylva?: Partial<SylvaDebugHook>;
  }
}

/** Whether the hook may be installed: dev builds, or a page URL with `debug=1`. */
export function debugEnabled(search: string, dev: boolean): boolean {
  return dev || new URLSearchParams(search).get('debug') === '1';
}

/** Whether this page runs with the hook (and so with a debug generator worker). */
export function debugMode(): boolean {
  return debugEnabled(window.location.search, import.meta.env.DEV);
}

/**
 * Dispatches `sylva:<name>` on `window` with `detail` when the hook is enabled (benchmarks
 * listen to `sylva:applied`: an answer is in the scene, ready for the next frame).
 */
export function emitDebug(name: 'applied', detail: object): void {
  if (!debugMode()) return;
  window.dispatchEvent(new CustomEvent(`sylva:${name}`, { detail }));
}

/**
 * Adds `parts` to the hook if enabled (several modules each add their own parts); returns a
 * function that removes exactly those parts again.
 */
export function installDebugHook(parts: Partial<SylvaDebugHook>): () => void {
  if (!debugMode()) return () => undefined;
  window.__sylva = { ...window.__sylva, ...parts };
  return () => {
    const hook = window.__sylva;
    if (!hook) return;
    const rest: Partial<SylvaDebugHook> = { ...hook };
    for (const key of Object.keys(parts) as (keyof SylvaDebugHook)[]) {
      if (rest[key] === parts[key]) delete rest[key];
    }
    if (Object.keys(rest).length === 0) delete window.__sylva;
    else window.__sylva = rest;
  };
}
