/**
 * The month-tint store the viewer writes and the leaf inspector reads: it notifies only on a
 * change of value (a new array with the same numbers is no change), and null (a bare tree) is
 * a value of its own. The SVG filter itself is checked in the browser (e2e/tests/seasons.spec.ts).
 */
import { describe, expect, it } from 'vitest';
import { MonthTintStore } from './monthTint';

describe('MonthTintStore', () => {
  it('notifies subscribers when the tint changes, not when the same numbers come again', () => {
    const store = new MonthTintStore();
    let calls = 0;
    const stop = store.subscribe(() => calls++);
    expect(store.get()).toBeNull();
    store.set([1, 0.98, 0.97]);
    store.set([1, 0.98, 0.97]);
    expect(calls).toBe(1);
    store.set([1.6, 0.5, 0.2]);
    expect(store.get()).toEqual([1.6, 0.5, 0.2]);
    store.set(null);
    store.set(null);
    expect(calls).toBe(3);
    stop();
    store.set([1, 1, 1]);
    expect(calls).toBe(3);
  });
});
