/** Tests of the undo/redo stack and its keyboard shortcuts. */
import { describe, expect, it } from 'vitest';
import type { Params, VolumePrimitive } from 'sylva-trees/core';
import {
  COALESCE_MS,
  historyShortcut,
  record,
  redo,
  startHistory,
  undo,
  type ChangeOptions,
  type History,
  type ShortcutKey,
  type Travel,
} from './history';

/** The history of params alone (no volumes), driven step by step as the app does. */
class ParamsHistory {
  h: History;
  constructor(initial: Params, limit?: number) {
    this.h = startHistory({ params: initial, volumes: [], edits: [] }, limit);
  }
  get current(): Params {
    return this.h.present.params;
  }
  get canUndo(): boolean {
    return this.h.past.length > 0;
  }
  get canRedo(): boolean {
    return this.h.future.length > 0;
  }
  get undoDepth(): number {
    return this.h.past.length;
  }
  record(params: Params, options: ChangeOptions): void {
    this.h = record(this.h, { ...this.h.present, params }, options);
  }
  private travel(step: Travel | null): { params: Params; frame: boolean } | null {
    if (step === null) return null;
    this.h = step.history;
    return { params: step.shown.params, frame: step.shown.frame };
  }
  undo() {
    return this.travel(undo(this.h));
  }
  redo() {
    return this.travel(redo(this.h));
  }
}

const base = { seed: 1, scale: 13, l1_length: 0.3 };

describe('history of params', () => {
  it('starts with nothing to undo or redo', () => {
    const h = new ParamsHistory(base);
    expect(h.canUndo).toBe(false);
    expect(h.canRedo).toBe(false);
    expect(h.undo()).toBeNull();
    expect(h.redo()).toBeNull();
    expect(h.current).toBe(base);
  });

  it('undoes and redoes discrete changes one at a time', () => {
    const h = new ParamsHistory(base);
    const a = { ...base, seed: 2 };
    const b = { ...a, scale: 20 };
    h.record(a, { key: null, now: 0 });
    h.record(b, { key: null, now: 1 });
    expect(h.undoDepth).toBe(2);
    expect(h.undo()?.params).toBe(a);
    expect(h.undo()?.params).toBe(base);
    expect(h.undo()).toBeNull();
    expect(h.canRedo).toBe(true);
    expect(h.redo()?.params).toBe(a);
    expect(h.redo()?.params).toBe(b);
    expect(h.redo()).toBeNull();
    expect(h.current).toBe(b);
  });

  it('a slider drag (rapid changes of one param) is one undo step', () => {
    const h = new ParamsHistory(base);
    let now = 0;
    let last = base;
    for (let i = 1; i <= 600; i++) {
      now += 16; // one change per frame for ~10 s
      last = { ...last, l1_length: 0.3 + i * 0.001 };
      h.record(last, { key: 'l1_length', now });
    }
    expect(h.undoDepth).toBe(1);
    expect(h.current).toBe(last);
    expect(h.undo()?.params).toBe(base);
    expect(h.redo()?.params).toBe(last);
  });

  it('a pause longer than the window, or another param, starts a new step', () => {
    const h = new ParamsHistory(base);
    const a = { ...base, l1_length: 0.4 };
    const b = { ...a, l1_length: 0.5 };
    const c = { ...b, scale: 14 };
    h.record(a, { key: 'l1_length', now: 0 });
    h.record(b, { key: 'l1_length', now: COALESCE_MS + 1 });
    h.record(c, { key: 'scale', now: COALESCE_MS + 2 });
    expect(h.undoDepth).toBe(3);
    expect(h.undo()?.params).toBe(b);
    expect(h.undo()?.params).toBe(a);
  });

  it('discrete changes (presets, Reset) never merge, even with a param edit just before', () => {
    const h = new ParamsHistory(base);
    const edited = { ...base, seed: 5 };
    const preset = { seed: 1, scale: 30, l1_length: 0.5 };
    h.record(edited, { key: 'seed', now: 0 });
    h.record(preset, { key: null, frame: true, now: 1 });
    h.record(base, { key: null, frame: true, now: 2 });
    expect(h.undoDepth).toBe(3);
    expect(h.undo()).toEqual({ params: preset, frame: true });
    expect(h.undo()).toEqual({ params: edited, frame: true });
    expect(h.undo()).toEqual({ params: base, frame: false });
    expect(h.redo()).toEqual({ params: edited, frame: false });
    expect(h.redo()).toEqual({ params: preset, frame: true });
  });

  it('a new change after undo drops the redo steps', () => {
    const h = new ParamsHistory(base);
    h.record({ ...base, seed: 2 }, { key: null, now: 0 });
    h.undo();
    h.record({ ...base, seed: 3 }, { key: null, now: 1 });
    expect(h.canRedo).toBe(false);
    expect(h.current.seed).toBe(3);
  });

  it('undo ends the coalescing window: the next drag is its own step', () => {
    const h = new ParamsHistory(base);
    h.record({ ...base, l1_length: 0.4 }, { key: 'l1_length', now: 0 });
    h.undo();
    h.record({ ...base, l1_length: 0.6 }, { key: 'l1_length', now: 10 });
    expect(h.undoDepth).toBe(1);
    expect(h.undo()?.params).toEqual(base);
  });

  it('recording the same params is a no-op; dragging back to the start removes the step', () => {
    const h = new ParamsHistory(base);
    h.record({ ...base }, { key: null, now: 0 });
    expect(h.canUndo).toBe(false);
    h.record({ ...base, scale: 15 }, { key: 'scale', now: 1 });
    h.record({ ...base, scale: 13 }, { key: 'scale', now: 2 });
    expect(h.canUndo).toBe(false);
    expect(h.current).toEqual(base);
  });

  it('keeps at most `limit` steps', () => {
    const h = new ParamsHistory(base, 5);
    for (let i = 2; i < 20; i++) h.record({ ...base, seed: i }, { key: null, now: i });
    expect(h.undoDepth).toBe(5);
    let last = h.current;
    while (h.canUndo) last = h.undo()?.params ?? last;
    expect(last.seed).toBe(14);
  });
});

describe('history of volumes', () => {
  const sphere: VolumePrimitive = {
    kind: 'sphere',
    group: 'crown',
    centre: [0, 5, 0],
    size: [2, 2, 2],
  };
  const at = (y: number): VolumePrimitive => ({ ...sphere, centre: [0, y, 0] });

  it('a gizmo drag of one primitive is one step; volume and param edits undo in order', () => {
    let h = startHistory({ params: base, volumes: [], edits: [] });
    h = record(h, { params: base, volumes: [at(5)], edits: [] }, { key: null, now: 0 });
    for (let i = 1; i <= 30; i++) {
      h = record(
        h,
        { params: base, volumes: [at(5 + i / 10)], edits: [] },
        { key: 'volume:0', now: i * 16 },
      );
    }
    const grown = { ...base, seed: 9 };
    h = record(h, { params: grown, volumes: [at(8)], edits: [] }, { key: null, now: 600 });
    expect(h.past).toHaveLength(3);
    const back = undo(h);
    expect(back?.shown.volumes).toEqual([at(8)]);
    const dragUndone = undo(back!.history);
    expect(dragUndone?.shown.volumes).toEqual([at(5)]);
    expect(dragUndone?.shown.params).toBe(base);
    const addUndone = undo(dragUndone!.history);
    expect(addUndone?.shown.volumes).toEqual([]);
    const redone = redo(addUndone!.history);
    expect(redone?.shown.volumes).toEqual([at(5)]);
  });

  it('the same volumes in a new array are no change', () => {
    const h = startHistory({ params: base, volumes: [at(1)], edits: [] });
    expect(
      record(h, { params: { ...base }, volumes: [at(1)], edits: [] }, { key: null, now: 0 }),
    ).toBe(h);
  });
});

describe('historyShortcut', () => {
  const key = (k: string, mods: Partial<ShortcutKey> = {}): ShortcutKey => ({
    key: k,
    ctrlKey: false,
    metaKey: false,
    shiftKey: false,
    altKey: false,
    ...mods,
  });

  it('maps Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y and the ⌘ variants', () => {
    expect(historyShortcut(key('z', { ctrlKey: true }))).toBe('undo');
    expect(historyShortcut(key('Z', { ctrlKey: true, shiftKey: true }))).toBe('redo');
    expect(historyShortcut(key('y', { ctrlKey: true }))).toBe('redo');
    expect(historyShortcut(key('z', { metaKey: true }))).toBe('undo');
    expect(historyShortcut(key('z', { metaKey: true, shiftKey: true }))).toBe('redo');
  });

  it('ignores plain keys, Alt combinations and other letters', () => {
    expect(historyShortcut(key('z'))).toBeNull();
    expect(historyShortcut(key('z', { ctrlKey: true, altKey: true }))).toBeNull();
    expect(historyShortcut(key('y', { ctrlKey: true, shiftKey: true }))).toBeNull();
    expect(historyShortcut(key('x', { ctrlKey: true }))).toBeNull();
  });
});
