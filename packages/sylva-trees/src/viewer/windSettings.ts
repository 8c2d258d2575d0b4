/** Wind settings of the viewer (not tree parameters): defaults, limits, validation, storage. */

/** What the wind controls set. */
export interface WindSettings {
  /** Wind on (off: the tree stands still, frames are time-independent). */
  enabled: boolean;
  /** Time stands still (the tree keeps its current pose). */
  paused: boolean;
  /** 0 (calm) .. 2 (storm). */
  strength: number;
  /** Compass angle the wind blows toward, degrees (0 = +x, 90 = +z). */
  direction: number;
  /** Gust amplitude 0..1 (a slow envelope on the strength). */
  gust: number;
}

/** A gentle breeze. */
export const DEFAULT_WIND: WindSettings = {
  enabled: true,
  paused: false,
  strength: 0.6,
  direction: 30,
  gust: 0.5,
};

/** Whether the visitor asked for reduced motion (the wind then starts paused). */
export function prefersReducedMotion(): boolean {
  try {
    return (
      typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches
    );
  } catch {
    return false;
  }
}

/** The settings a first visit starts with: a breeze, paused when reduced motion is preferred. */
export function initialWind(reducedMotion: boolean = prefersReducedMotion()): WindSettings {
  return { ...DEFAULT_WIND, paused: reducedMotion };
}

/** Slider ranges of the numeric settings. */
export const WIND_LIMITS = {
  strength: { min: 0, max: 2, step: 0.05 },
  direction: { min: 0, max: 355, step: 5 },
  gust: { min: 0, max: 1, step: 0.05 },
} as const;

/** Gust frequency (Hz): about one gust every 7 s. */
export const GUST_FREQUENCY = 0.15;

/** localStorage key of the saved settings (JSON). */
export const WIND_STORAGE_KEY = 'sylva.wind.v1';

/** Minimal storage interface (localStorage or a fake). */
export interface WindStore {
  getItem(key: string): string | null;
  setItem(key: string, value: string): void;
}

function number(value: unknown, limits: { min: number; max: number }, fallback: number): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) return fallback;
  return Math.min(Math.max(value, limits.min), limits.max);
}

/** Any value (parsed JSON, a partial object) as valid settings, on top of `base`. */
export function sanitizeWind(value: unknown, base: WindSettings = DEFAULT_WIND): WindSettings {
  if (typeof value !== 'object' || value === null) return { ...base };
  const v = value as Record<string, unknown>;
  const direction =
    typeof v.direction === 'number' && Number.isFinite(v.direction)
      ? ((v.direction % 360) + 360) % 360
      : base.direction;
  return {
    enabled: typeof v.enabled === 'boolean' ? v.enabled : base.enabled,
    paused: typeof v.paused === 'boolean' ? v.paused : base.paused,
    strength: number(v.strength, WIND_LIMITS.strength, base.strength),
    direction,
    gust: number(v.gust, WIND_LIMITS.gust, base.gust),
  };
}

/**
 * The saved settings, or the first-visit ones (`initialWind`) when storage is missing,
 * unreadable or invalid.
 */
export function loadWind(
  storage: WindStore | null,
  initial: WindSettings = initialWind(),
): WindSettings {
  try {
    const text = storage?.getItem(WIND_STORAGE_KEY);
    return text ? sanitizeWind(JSON.parse(text), initial) : { ...initial };
  } catch {
    return { ...initial };
  }
}

/** Saves the settings (a full or denied storage is ignored). */
export function saveWind(storage: WindStore | null, settings: WindSettings): void {
  try {
    storage?.setItem(WIND_STORAGE_KEY, JSON.stringify(settings));
  } catch {
    // the wind simply starts from the defaults next time
  }
}

/** Unit `[x, z]` vector of a direction in degrees. */
export function windDirectionVector(degrees: number): [number, number] {
  const a = (degrees * Math.PI) / 180;
  return [Math.cos(a), Math.sin(a)];
}
