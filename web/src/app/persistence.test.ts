/** Tests of the initial-params choice between page URL, localStorage and defaults. */
import { describe, expect, it } from 'vitest';
import { defaultParams } from 'sylva-trees/core';
import { realRegistry } from 'sylva-trees/testing';
import { loadInitialParams, STORAGE_KEY, type KeyValueStore } from './persistence';

const registry = realRegistry();

function store(initial: Record<string, string>): KeyValueStore {
  const data = new Map(Object.entries(initial));
  return {
    getItem: (k) => data.get(k) ?? null,
    setItem: (k, v) => void data.set(k, v),
  };
}

describe('loadInitialParams', () => {
  it('prefers the URL when it carries params', () => {
    const r = loadInitialParams(registry, '?v=1&seed=5', store({ [STORAGE_KEY]: 'v=1&seed=9' }));
    expect(r.source).toBe('url');
    expect(r.params.seed).toBe(5);
  });

  it('restores from storage when the query has no params (debug flag alone is not params)', () => {
    const r = loadInitialParams(registry, '?debug=1', store({ [STORAGE_KEY]: 'v=1&seed=9' }));
    expect(r.source).toBe('storage');
    expect(r.params.seed).toBe(9);
  });

  it('falls back to defaults without storage', () => {
    const r = loadInitialParams(registry, '', null);
    expect(r.source).toBe('defaults');
    expect(r.params).toEqual(defaultParams(registry));
  });

  it('reports bad stored values like bad URL values', () => {
    const r = loadInitialParams(registry, '', store({ [STORAGE_KEY]: 'v=1&seed=abc' }));
    expect(r.params.seed).toBe(defaultParams(registry).seed);
    expect(r.messages.length).toBe(1);
  });

  it('survives a throwing storage', () => {
    const throwing: KeyValueStore = {
      getItem: () => {
        throw new Error('denied');
      },
      setItem: () => undefined,
    };
    expect(loadInitialParams(registry, '', throwing).source).toBe('defaults');
  });
});
