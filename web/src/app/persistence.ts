/** Share-URL and localStorage persistence of the current params (load on start, debounced save). */
import type { Params, ParamSpec } from 'sylva-trees/core';
import { buildSearch, decodeQuery, type DecodeResult, encodeParams } from 'sylva-trees/url';

/** localStorage key holding the last params as a share query string. */
export const STORAGE_KEY = 'sylva.params.v1';

/** Where the initial params came from. */
export type ParamsSource = 'url' | 'storage' | 'defaults';

/** Minimal storage interface (localStorage, or a fake in tests). */
export interface KeyValueStore {
  getItem(key: string): string | null;
  setItem(key: string, value: string): void;
}

/** The browser's localStorage, or null where it is unavailable (privacy modes, sandboxed frames). */
export function browserStorage(): KeyValueStore | null {
  try {
    return window.localStorage;
  } catch {
    return null;
  }
}

/** Initial params: from the page query if it carries any, else from storage, else defaults. */
export function loadInitialParams(
  registry: readonly ParamSpec[],
  search: string,
  storage: KeyValueStore | null,
): DecodeResult & { source: ParamsSource } {
  const fromUrl = decodeQuery(registry, search);
  if (fromUrl.hasParams) return { ...fromUrl, source: 'url' };
  let saved: string | null;
  try {
    saved = storage?.getItem(STORAGE_KEY) ?? null;
  } catch {
    saved = null;
  }
  if (saved) {
    const fromStorage = decodeQuery(registry, saved);
    return { ...fromStorage, source: 'storage' };
  }
  return { ...fromUrl, source: 'defaults' };
}

/** Writes params to the URL (history.replaceState) and storage, at most once per `delayMs`. */
export class ParamsSync {
  private timer: ReturnType<typeof setTimeout> | null = null;
  private latest: { registry: readonly ParamSpec[]; params: Params } | null = null;

  constructor(
    private readonly storage: KeyValueStore | null,
    private readonly delayMs = 300,
  ) {}

  /** Schedules a save of `params`; a newer call within the delay replaces it. */
  schedule(registry: readonly ParamSpec[], params: Params): void {
    this.latest = { registry, params };
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = setTimeout(() => this.flush(), this.delayMs);
  }

  /** Saves the scheduled params now. */
  flush(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    const latest = this.latest;
    if (!latest) return;
    this.latest = null;
    const search = buildSearch(latest.registry, latest.params, window.location.search);
    if (search !== window.location.search) {
      const url = `${window.location.pathname}${search}${window.location.hash}`;
      window.history.replaceState(window.history.state, '', url);
    }
    try {
      this.storage?.setItem(STORAGE_KEY, encodeParams(latest.registry, latest.params));
    } catch {
      // storage full or denied: the URL still carries the state
    }
  }

  /** Drops any scheduled save. */
  cancel(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    this.latest = null;
  }
}
