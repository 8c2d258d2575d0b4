/** The `window.__sylva` debug hook (dev mode or `?debug=1` only). */

/** What the debug hook exposes to tests and the console. */
export interface SylvaDebugHook {
  /** Makes the generator worker panic (tests the crash-recovery path). */
  panic(): void;
}

declare global {
  interface Window {
    __sylva?: SylvaDebugHook;
  }
}

/** Whether the hook may be installed: dev builds, or a page URL with `debug=1`. */
export function debugEnabled(search: string, dev: boolean): boolean {
  return dev || new URLSearchParams(search).get('debug') === '1';
}

/** Installs the hook if enabled; returns an uninstall function. */
export function installDebugHook(hook: SylvaDebugHook): () => void {
  if (!debugEnabled(window.location.search, import.meta.env.DEV)) return () => undefined;
  window.__sylva = hook;
  return () => {
    if (window.__sylva === hook) delete window.__sylva;
  };
}
