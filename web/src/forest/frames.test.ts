import { describe, expect, it } from 'vitest';
import { ARRIVING_GAP, SOFTWARE_FIRST_FRAME_MS, drawNow, type FrameState } from './frames';

const base: FrameState = {
  loading: false,
  dirty: true,
  arriving: true,
  software: false,
  now: 10_000,
  firstAddedAt: 9_900,
  lastDraw: { at: 0, ms: 0 },
};

describe('drawNow', () => {
  it('draws nothing before the first tree or when nothing changed', () => {
    expect(drawNow({ ...base, loading: true })).toBe(false);
    expect(drawNow({ ...base, dirty: false })).toBe(false);
    expect(drawNow({ ...base, arriving: false, dirty: false })).toBe(false);
  });

  it('draws a changed view at once when every tree is in', () => {
    const busy = { ...base, software: true, arriving: false, lastDraw: { at: 9_990, ms: 1_500 } };
    expect(drawNow(busy)).toBe(true);
  });

  it('spaces frames out while trees arrive', () => {
    // On a GPU the first frame is drawn at once, then each waits twice the last one's time.
    expect(drawNow(base)).toBe(true);
    const last = { at: 9_000, ms: 600 };
    expect(drawNow({ ...base, lastDraw: last, now: 9_000 + ARRIVING_GAP * 600 - 1 })).toBe(false);
    expect(drawNow({ ...base, lastDraw: last, now: 9_000 + ARRIVING_GAP * 600 })).toBe(true);
  });

  it('holds a software renderer’s first frame while the first trees are still being joined', () => {
    // The regression: a 1.2-1.7 s frame after the first few trees held back the other trees.
    const soft = { ...base, software: true, firstAddedAt: 5_000 };
    expect(drawNow({ ...soft, now: 5_000 + SOFTWARE_FIRST_FRAME_MS - 1 })).toBe(false);
    // A long load still appears as it grows, its frames spaced out.
    expect(drawNow({ ...soft, now: 5_000 + SOFTWARE_FIRST_FRAME_MS })).toBe(true);
    const last = { at: 8_000, ms: 1_500 };
    expect(drawNow({ ...soft, now: 10_000, lastDraw: last })).toBe(false);
    expect(drawNow({ ...soft, now: 11_000, lastDraw: last })).toBe(true);
    // Every tree in: drawn at once.
    expect(drawNow({ ...soft, now: 5_010, arriving: false })).toBe(true);
  });
});
