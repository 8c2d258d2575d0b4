/**
 * The stats overlay's state (counts, timings, hash, busy) outside React: a new tree updates
 * only the overlay, not the whole app (`useSyncExternalStore`), so a slider drag does not
 * re-render the panel once per answer.
 */
import type { TreeMeta } from 'sylva-trees/core';

/** Per-tree numbers shown in the stats overlay. */
export type TreeStats = Pick<TreeMeta, 'vertices' | 'triangles' | 'hash' | 'total_ms' | 'stems'> & {
  /** Request to geometry built on the main thread: generation + transfer + BufferGeometry (ms). */
  roundTripMs: number | null;
  /** GPU upload + draw time when measured (null: drawn on the next animation frame). */
  drawMs: number | null;
  /** The bark on screen is a quick preview (a drag is in progress). */
  preview: boolean;
};

/** What the overlay shows. */
export interface StatsState {
  stats: TreeStats | null;
  busy: boolean;
}

/** A tiny external store of [`StatsState`]. */
export class StatsStore {
  private state: StatsState = { stats: null, busy: false };
  private readonly listeners = new Set<() => void>();

  /** The current state (a new object after every change). */
  readonly get = (): StatsState => this.state;

  /** Subscribes to changes; returns the unsubscribe function. */
  readonly subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };

  /** Merges `patch` into the state and notifies (nothing happens when nothing changed). */
  set(patch: Partial<StatsState>): void {
    const next = { ...this.state, ...patch };
    if (next.stats === this.state.stats && next.busy === this.state.busy) return;
    this.state = next;
    for (const listener of this.listeners) listener();
  }

  /** Sets the hash of the stats shown (it arrives after the tree). */
  setHash(hash: string): void {
    const stats = this.state.stats;
    if (stats && stats.hash !== hash) this.set({ stats: { ...stats, hash } });
  }
}
