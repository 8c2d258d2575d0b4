/**
 * Undo/redo of parameter changes (plain module, no React). Every change is a snapshot of the
 * whole params; rapid changes of one parameter (a slider drag, typing a number) coalesce into
 * one undo step, while presets, Reset and Randomize are always steps of their own.
 */
import type { Params } from '../core/types';

/** Changes of one parameter closer together than this (ms) are one undo step. */
export const COALESCE_MS = 1000;
/** Undo steps kept; older ones are dropped. */
export const HISTORY_LIMIT = 200;

/** A snapshot plus how to show it (`frame`: re-frame the camera, as for a preset). */
export interface HistoryEntry {
  params: Params;
  frame: boolean;
}

/** How a change is recorded. */
export interface ChangeOptions {
  /** The parameter a continuous edit changes (coalesced); null for a discrete step. */
  key: string | null;
  /** Re-frame the camera when this step is undone or redone. */
  frame?: boolean;
  /** Timestamp in ms (performance.now() in the app, a counter in tests). */
  now: number;
}

function sameParams(a: Params, b: Params): boolean {
  const keys = Object.keys(a);
  if (keys.length !== Object.keys(b).length) return false;
  return keys.every((k) => Object.is(a[k], b[k]));
}

/** The undo stack: `past` steps, the present, and `future` steps to redo. */
export class ParamsHistory {
  private past: HistoryEntry[] = [];
  private future: HistoryEntry[] = [];
  private present: HistoryEntry;
  private lastKey: string | null = null;
  private lastAt = Number.NEGATIVE_INFINITY;

  constructor(
    initial: Params,
    private readonly limit = HISTORY_LIMIT,
    private readonly coalesceMs = COALESCE_MS,
  ) {
    this.present = { params: initial, frame: false };
  }

  /** The current params. */
  get current(): Params {
    return this.present.params;
  }

  get canUndo(): boolean {
    return this.past.length > 0;
  }

  get canRedo(): boolean {
    return this.future.length > 0;
  }

  /** Number of undo steps available. */
  get undoDepth(): number {
    return this.past.length;
  }

  /**
   * Records that the params became `next`. A change with the same `key` as the previous one,
   * within the coalescing window of it, extends that step instead of starting a new one; a
   * step that ends where it started disappears. Clears the redo steps. No-op if nothing changed.
   */
  record(next: Params, { key, frame = false, now }: ChangeOptions): void {
    if (sameParams(next, this.present.params)) return;
    this.future = [];
    const coalesce = key !== null && key === this.lastKey && now - this.lastAt <= this.coalesceMs;
    if (coalesce) {
      this.present = { params: next, frame: this.present.frame || frame };
      const before = this.past[this.past.length - 1];
      if (before && sameParams(before.params, next)) {
        // Dragged back to where the step began: nothing left to undo in this step.
        this.past.pop();
        this.present = before;
        this.seal();
        return;
      }
    } else {
      this.past.push(this.present);
      if (this.past.length > this.limit) this.past.shift();
      this.present = { params: next, frame };
    }
    this.lastKey = key;
    this.lastAt = now;
  }

  /** Ends the current coalescing window: the next change starts a new step. */
  seal(): void {
    this.lastKey = null;
    this.lastAt = Number.NEGATIVE_INFINITY;
  }

  /** Steps back; returns the params to show and whether to re-frame, or null at the start. */
  undo(): HistoryEntry | null {
    const previous = this.past.pop();
    if (!previous) return null;
    const undone = this.present;
    this.future.push(undone);
    this.present = previous;
    this.seal();
    return { params: previous.params, frame: undone.frame };
  }

  /** Steps forward again; null when there is nothing to redo. */
  redo(): HistoryEntry | null {
    const next = this.future.pop();
    if (!next) return null;
    this.past.push(this.present);
    this.present = next;
    this.seal();
    return { params: next.params, frame: next.frame };
  }
}

/** The keyboard event fields a shortcut depends on. */
export interface ShortcutKey {
  key: string;
  ctrlKey: boolean;
  metaKey: boolean;
  shiftKey: boolean;
  altKey: boolean;
}

/** Ctrl+Z (⌘Z) undoes; Ctrl+Shift+Z and Ctrl+Y (⌘⇧Z, ⌘Y) redo; anything else is not ours. */
export function historyShortcut(event: ShortcutKey): 'undo' | 'redo' | null {
  if (!(event.ctrlKey || event.metaKey) || event.altKey) return null;
  const key = event.key.toLowerCase();
  if (key === 'z') return event.shiftKey ? 'redo' : 'undo';
  if (key === 'y' && !event.shiftKey) return 'redo';
  return null;
}
