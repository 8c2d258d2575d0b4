/**
 * When the forest view draws a frame. The forest is drawn on demand (the camera moved, trees
 * were added or placed again, the canvas resized), and while the unique trees are still
 * arriving from the generation pool frames are spaced out: each one waits `ARRIVING_GAP` times
 * the last frame's time, leaving the GPU to the impostor bakes. A software renderer (no GPU:
 * SwiftShader, llvmpipe) shades every pixel on the CPU the generation workers need, and a forest
 * frame took 1.2-1.7 s of it on 2 cores: a frame drawn after the first few trees held back every
 * tree still to come by that much (16 trees shown 2.5-3.4 s after the click instead of 1.8 s).
 * So there the first frame also waits until `SOFTWARE_FIRST_FRAME_MS` after the first tree was
 * added, unless every tree is in by then: a short load is drawn once, a long one still appears
 * as it grows.
 */

/** While trees arrive, the next frame waits this many times the last frame's time. */
export const ARRIVING_GAP = 2;

/** With a software renderer, while trees arrive, no frame before this long (ms) after the first tree was added. */
export const SOFTWARE_FIRST_FRAME_MS = 2500;

/** What the decision reads (times in ms, `performance.now()`). */
export interface FrameState {
  /** No tree added yet: nothing to draw. */
  loading: boolean;
  /** The view changed since the last frame drawn. */
  dirty: boolean;
  /** More trees are on their way. */
  arriving: boolean;
  /** The renderer shades on the CPU. */
  software: boolean;
  now: number;
  /** When the first tree was added. */
  firstAddedAt: number;
  /** Start and duration of the last frame drawn (`ms` 0 before the first). */
  lastDraw: { at: number; ms: number };
}

/** Whether to draw a frame now (see the module's comment). */
export function drawNow(s: FrameState): boolean {
  if (s.loading || !s.dirty) return false;
  if (!s.arriving) return true;
  if (s.software && s.now - s.firstAddedAt < SOFTWARE_FIRST_FRAME_MS) return false;
  return s.now - s.lastDraw.at >= ARRIVING_GAP * s.lastDraw.ms;
}
