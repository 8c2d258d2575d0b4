import { describe, expect, it } from 'vitest';
import { canShareMemory } from './threads';

describe('canShareMemory', () => {
  it('is true only in a cross-origin isolated scope with SharedArrayBuffer', () => {
    expect(typeof SharedArrayBuffer).toBe('function');
    expect(canShareMemory({ crossOriginIsolated: true })).toBe(true);
    expect(canShareMemory({ crossOriginIsolated: false })).toBe(false);
    // An older browser without the property, or a page without the headers.
    expect(canShareMemory({})).toBe(false);
  });
});
