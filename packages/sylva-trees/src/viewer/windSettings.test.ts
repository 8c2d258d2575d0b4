import { describe, expect, it } from 'vitest';
import {
  DEFAULT_WIND,
  initialWind,
  loadWind,
  sanitizeWind,
  saveWind,
  WIND_LIMITS,
  WIND_STORAGE_KEY,
  windDirectionVector,
  type WindStore,
} from './windSettings';

function memoryStore(
  initial: Record<string, string> = {},
): WindStore & { data: Record<string, string> } {
  const data = { ...initial };
  return {
    data,
    getItem: (key) => data[key] ?? null,
    setItem: (key, value) => {
      data[key] = value;
    },
  };
}

describe('wind settings', () => {
  it('round-trip through storage', () => {
    const store = memoryStore();
    const settings = { enabled: false, paused: true, strength: 1.25, direction: 200, gust: 0.8 };
    saveWind(store, settings);
    expect(JSON.parse(store.data[WIND_STORAGE_KEY] ?? '')).toEqual(settings);
    expect(loadWind(store)).toEqual(settings);
  });

  it('start from a breeze, paused when reduced motion is preferred', () => {
    expect(loadWind(memoryStore(), initialWind(false))).toEqual(DEFAULT_WIND);
    expect(loadWind(null, initialWind(true))).toEqual({ ...DEFAULT_WIND, paused: true });
    expect(DEFAULT_WIND.enabled).toBe(true);
    expect(DEFAULT_WIND.strength).toBeGreaterThan(0);
  });

  it('ignore broken storage and clamp invalid values', () => {
    const initial = initialWind(false);
    expect(loadWind(memoryStore({ [WIND_STORAGE_KEY]: '{not json' }), initial)).toEqual(initial);
    const throwing: WindStore = {
      getItem: () => {
        throw new Error('denied');
      },
      setItem: () => {
        throw new Error('full');
      },
    };
    expect(loadWind(throwing, initial)).toEqual(initial);
    expect(() => saveWind(throwing, initial)).not.toThrow();
    const odd = sanitizeWind({ strength: 99, gust: -1, direction: -90, enabled: 'yes', paused: 1 });
    expect(odd.strength).toBe(WIND_LIMITS.strength.max);
    expect(odd.gust).toBe(WIND_LIMITS.gust.min);
    expect(odd.direction).toBe(270);
    expect(odd.enabled).toBe(DEFAULT_WIND.enabled);
    expect(odd.paused).toBe(DEFAULT_WIND.paused);
    expect(sanitizeWind({ strength: Number.NaN }).strength).toBe(DEFAULT_WIND.strength);
    expect(sanitizeWind(null)).toEqual(DEFAULT_WIND);
    // A partial change keeps the rest of the base.
    const base = { ...DEFAULT_WIND, strength: 1.7 };
    expect(sanitizeWind({ paused: true }, base)).toEqual({ ...base, paused: true });
  });

  it('direction angles are unit vectors in the ground plane', () => {
    for (const [deg, x, z] of [
      [0, 1, 0],
      [90, 0, 1],
      [180, -1, 0],
    ] as const) {
      const [vx, vz] = windDirectionVector(deg);
      expect(vx).toBeCloseTo(x, 9);
      expect(vz).toBeCloseTo(z, 9);
    }
  });
});
