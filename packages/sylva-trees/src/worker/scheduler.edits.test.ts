/**
 * The hand edit list in the scheduler's requests: sent with the params only when non-empty (so
 * today's trees are requested byte for byte as before), and kept for the settle of a drag.
 */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { Edit } from '../core/edits';
import { fakeWorkers, result } from './scheduler.fixtures';
import { GenerationScheduler } from './scheduler';

beforeEach(() => {
  vi.useFakeTimers();
});

afterEach(() => {
  vi.useRealTimers();
});

function setup() {
  const { factory, current } = fakeWorkers();
  const scheduler = new GenerationScheduler(factory, {
    onReady: () => undefined,
    onResult: () => undefined,
    onError: () => undefined,
    onBusyChange: () => undefined,
  });
  current().ready();
  return { scheduler, current };
}

const stroke: Edit = {
  op: 'paint',
  points: [[2, 6, 0]],
  radius: 0.6,
  density: 400,
  segment: 0.25,
  kill: 0.4,
};

describe('GenerationScheduler edits', () => {
  it('sends the edits with the params, and no key at all for an empty list', () => {
    const { scheduler, current } = setup();
    const a = scheduler.request({ seed: 1 }, undefined, { edits: [] });
    expect(current().posted.at(-1)).toEqual({ type: 'generate', id: a, params: { seed: 1 } });
    current().emit(result(a));
    const b = scheduler.request({ seed: 1 }, undefined, { edits: [stroke] });
    expect(current().posted.at(-1)).toEqual({
      type: 'generate',
      id: b,
      params: { seed: 1 },
      edits: [stroke],
    });
  });

  it('a stroke drawn interactively settles into the full tree with the same edits', () => {
    const { scheduler, current } = setup();
    const a = scheduler.request({ seed: 1 }, undefined, { interactive: true, edits: [stroke] });
    expect(current().posted.at(-1)).toMatchObject({ id: a, preview: true, edits: [stroke] });
    current().emit(result(a));
    const b = scheduler.settle();
    expect(current().posted.at(-1)).toEqual({
      type: 'generate',
      id: b,
      params: { seed: 1 },
      edits: [stroke],
    });
  });

  it('latest wins: a newer edit list replaces one not yet sent', () => {
    const { scheduler, current } = setup();
    const a = scheduler.request({ seed: 1 });
    scheduler.request({ seed: 1 }, undefined, { edits: [stroke] });
    const cut: Edit = { op: 'cut', at: [1, 4, 0] };
    const c = scheduler.request({ seed: 1 }, undefined, { edits: [stroke, cut] });
    current().emit(result(a));
    expect(current().posted.at(-1)).toMatchObject({ id: c, edits: [stroke, cut] });
    expect(current().posted.filter((p) => p.type === 'generate')).toHaveLength(2);
  });

  it('asks for the end grain only when told (the Cut tool chosen), at full quality', () => {
    const { scheduler, current } = setup();
    const a = scheduler.request({ seed: 1 }, undefined, { interactive: true });
    current().emit(result(a));
    const b = scheduler.request({ seed: 1 }, undefined, { edits: [stroke], endGrain: true });
    expect(current().posted.at(-1)).toEqual({
      type: 'generate',
      id: b,
      params: { seed: 1 },
      edits: [stroke],
      endGrain: true,
    });
    current().emit(result(b));
    // Nothing left to settle: the request for the end grain was the full tree.
    expect(scheduler.settle()).toBeNull();
    const c = scheduler.request({ seed: 2 });
    expect(current().posted.at(-1)).toEqual({ type: 'generate', id: c, params: { seed: 2 } });
  });
});
