/**
 * Undo/redo of the editor's state (plain module, no React; immutable: every function returns a
 * new history). Every change is a snapshot of the whole params, growth volumes and hand edits
 * (a paint stroke or a bend drag is recorded once, when the pointer is released); rapid changes
 * of one thing (a slider drag, typing a number, a gizmo drag of one primitive) coalesce into one
 * undo step, while presets, Reset, Randomize and adding or removing a primitive are always
 * steps of their own.
 */
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';

/** Changes of one key closer together than this (ms) are one undo step. */
export const COALESCE_MS = 1000;
/** Undo steps kept; older ones are dropped. */
export const HISTORY_LIMIT = 200;

/** What undo restores: the params, the growth volumes and the hand edit list. */
export interface Snapshot {
  params: Params;
  volumes: VolumePrimitive[];
  edits: Edit[];
}

/** A snapshot plus how to show it (`frame`: re-frame the camera, as for a preset). */
export interface HistoryEntry extends Snapshot {
  frame: boolean;
}

/** How a change is recorded. */
export interface ChangeOptions {
  /** What a continuous edit changes (coalesced: a param id, `volume:<index>`); null: a step. */
  key: string | null;
  /** Re-frame the camera when this step is undone or redone. */
  frame?: boolean;
  /** Timestamp in ms (performance.now() in the app, a counter in tests). */
  now: number;
}

/** The undo stack: `past` steps, the present, and `future` steps to redo. */
export interface History {
  readonly past: readonly HistoryEntry[];
  readonly present: HistoryEntry;
  readonly future: readonly HistoryEntry[];
  /** The key and time of the last change (its coalescing window). */
  readonly lastKey: string | null;
  readonly lastAt: number;
  readonly limit: number;
  readonly coalesceMs: number;
}

function sameParams(a: Params, b: Params): boolean {
  const keys = Object.keys(a) as (keyof Params)[];
  if (keys.length !== Object.keys(b).length) return false;
  return keys.every((k) => Object.is(a[k], b[k]));
}

/** Whether two lists hold the same values (the same array is, without a look). */
function sameList(a: readonly unknown[], b: readonly unknown[]): boolean {
  return a === b || JSON.stringify(a) === JSON.stringify(b);
}

/** Whether two snapshots hold the same params, volumes and edits. */
export function sameSnapshot(a: Snapshot, b: Snapshot): boolean {
  return (
    sameParams(a.params, b.params) && sameList(a.volumes, b.volumes) && sameList(a.edits, b.edits)
  );
}

/** A history whose present is `initial`, with nothing to undo. */
export function startHistory(
  initial: Snapshot,
  limit = HISTORY_LIMIT,
  coalesceMs = COALESCE_MS,
): History {
  const present = { ...initial, frame: false };
  return { past: [], present, future: [], ...sealed, limit, coalesceMs };
}

/** No coalescing window open: the next change starts a new step. */
const sealed = { lastKey: null, lastAt: Number.NEGATIVE_INFINITY } as const;

export const canUndo = (h: History): boolean => h.past.length > 0;
export const canRedo = (h: History): boolean => h.future.length > 0;

/**
 * Records that the state became `next`. A change with the same `key` as the previous one,
 * within the coalescing window of it, extends that step instead of starting a new one; a
 * step that ends where it started disappears. Clears the redo steps. No-op if nothing changed.
 */
export function record(h: History, next: Snapshot, options: ChangeOptions): History {
  const { key, frame = false, now } = options;
  if (sameSnapshot(next, h.present)) return h;
  const coalesce = key !== null && key === h.lastKey && now - h.lastAt <= h.coalesceMs;
  if (!coalesce) {
    const past = [...h.past, h.present].slice(-h.limit);
    return { ...h, past, present: { ...next, frame }, future: [], lastKey: key, lastAt: now };
  }
  const before = h.past[h.past.length - 1];
  if (before && sameSnapshot(before, next)) {
    // Dragged back to where the step began: nothing left to undo in this step.
    return { ...h, past: h.past.slice(0, -1), present: before, future: [], ...sealed };
  }
  const present = { ...next, frame: h.present.frame || frame };
  return { ...h, present, future: [], lastKey: key, lastAt: now };
}

/** Ends the current coalescing window: the next change starts a new step. */
export function seal(h: History): History {
  return { ...h, ...sealed };
}

/** A step of undo or redo: the new history and the snapshot to show. */
export interface Travel {
  history: History;
  /** The new present; `frame`: re-frame the camera (the undone or redone step asked for it). */
  shown: HistoryEntry;
}

/** Steps back; null at the start. */
export function undo(h: History): Travel | null {
  const previous = h.past[h.past.length - 1];
  if (!previous) return null;
  const undone = h.present;
  const past = h.past.slice(0, -1);
  const history = { ...h, past, present: previous, future: [...h.future, undone], ...sealed };
  return { history, shown: { ...previous, frame: undone.frame } };
}

/** Steps forward again; null when there is nothing to redo. */
export function redo(h: History): Travel | null {
  const next = h.future[h.future.length - 1];
  if (!next) return null;
  const future = h.future.slice(0, -1);
  return {
    history: { ...h, past: [...h.past, h.present], present: next, future, ...sealed },
    shown: next,
  };
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
