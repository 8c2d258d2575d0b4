/**
 * The month-tint store the viewer writes and the leaf inspector reads: it notifies only on a
 * change of value (a new array with the same numbers is no change), and null (a bare tree) is
 * a value of its own. The SVG filter itself is checked in the browser (e2e/tests/seasons.spec.ts).
 */
import { describe, expect, it } from 'vitest';
import { drawingTint, MonthTintStore } from './monthTint';

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

describe('drawingTint', () => {
  it("keeps the blade's lightness and the tint's hue", () => {
    // A grey tint (the crown's shade) leaves the drawing as drawn.
    for (const c of drawingTint([0.44, 0.44, 0.44])) expect(c).toBeCloseTo(1, 5);
    // An aspen's October gold: many times the blade's red; the drawing stays as light, gold.
    const [r, g, b] = drawingTint([12, 2.5, 0.8]);
    const luma = 0.2126 * r * 0.0732 + 0.7152 * g * 0.233 + 0.0722 * b * 0.0272;
    expect(luma).toBeCloseTo(0.2126 * 0.0732 + 0.7152 * 0.233 + 0.0722 * 0.0272, 5);
    expect(r / g).toBeCloseTo(12 / 2.5, 5);
    expect(r).toBeGreaterThan(1);
    expect(b).toBeLessThan(0.5);
  });
});
