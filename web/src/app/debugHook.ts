/** The `window.__sylva` debug hook (dev mode or `?debug=1` only). */

/** What the debug hook exposes to tests and the console. */
export interface SylvaDebugHook {
  /** Makes the generator worker panic (tests the crash-recovery path). */
  panic(): void;
  /** Makes the generator worker busy-loop for `ms` (tests the time limit). */
  hang(ms: number): void;
  /** Sets the generation time limit in ms (tests use a short one). */
  setTimeLimit(ms: number): void;
  /** Geometries alive on the GPU (three.js `renderer.info.memory.geometries`), for leak tests. */
  geometries(): number | null;
  /** Growth overlay: markers and primitive wireframes drawn now, and whether a gizmo drag runs. */
  growth(): { markers: number; volumes: number; dragging: boolean };
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

/**
 * Adds `parts` to the hook if enabled (several modules each add their own parts); returns a
 * function that removes exactly those parts again.
 */
export function installDebugHook(parts: Partial<SylvaDebugHook>): () => void {
  if (!debugEnabled(window.location.search, import.meta.env.DEV)) return () => undefined;
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
