/** The editor's reducer: params, growth volumes and hand edits share one undo history. */
import { describe, expect, it } from 'vitest';
import type { Edit, VolumePrimitive } from 'sylva-trees/core';
import { editorReducer, initialEditor, undoable, type EditorAction } from './editor';

const sphere: VolumePrimitive = {
  kind: 'sphere',
  group: 'crown',
  centre: [0, 5, 0],
  size: [2, 2, 2],
};
const moved = (y: number): VolumePrimitive => ({ ...sphere, centre: [0, y, 0] });

const run = (actions: EditorAction[], volumes: VolumePrimitive[] = []) =>
  actions.reduce(editorReducer, initialEditor(volumes));

describe('editorReducer', () => {
  it('edits before the generator is ready change nothing; load starts an empty history', () => {
    const before = initialEditor([sphere]);
    expect(editorReducer(before, { type: 'change', params: { seed: 2 }, key: null, now: 0 })).toBe(
      before,
    );
    const loaded = editorReducer(before, { type: 'load', params: { seed: 1 } });
    expect(loaded.params).toEqual({ seed: 1 });
    expect(loaded.volumes).toEqual([sphere]);
    expect(undoable(loaded)).toEqual({ canUndo: false, canRedo: false });
  });

  it('volume edits undo and redo, a gizmo drag as one step, in order with param edits', () => {
    const dragged = Array.from({ length: 20 }, (_, i): EditorAction => ({
      type: 'change',
      volumes: [moved(5 + i / 4)],
      key: 'volume:0',
      now: 100 + i * 16,
    }));
    const state = run([
      { type: 'load', params: { seed: 1 } },
      // Adding a primitive also turns growth on: one step.
      { type: 'change', params: { seed: 1, growth_mode: 1 }, volumes: [sphere], key: null, now: 0 },
      ...dragged,
      { type: 'change', params: { seed: 1, growth_mode: 1, scale: 9 }, key: 'scale', now: 900 },
    ]);
    expect(state.volumes).toEqual([moved(9.75)]);
    const scaleUndone = editorReducer(state, { type: 'undo' });
    expect(scaleUndone.params).toEqual({ seed: 1, growth_mode: 1 });
    expect(scaleUndone.volumes).toEqual([moved(9.75)]);
    const dragUndone = editorReducer(scaleUndone, { type: 'undo' });
    expect(dragUndone.volumes).toEqual([sphere]);
    const addUndone = editorReducer(dragUndone, { type: 'undo' });
    expect(addUndone.volumes).toEqual([]);
    expect(addUndone.params).toEqual({ seed: 1 });
    expect(undoable(addUndone)).toEqual({ canUndo: false, canRedo: true });
    const redone = editorReducer(addUndone, { type: 'redo' });
    expect(redone.volumes).toEqual([sphere]);
    expect(redone.params).toEqual({ seed: 1, growth_mode: 1 });
    expect(
      editorReducer(editorReducer(redone, { type: 'redo' }), { type: 'redo' }).volumes,
    ).toEqual([moved(9.75)]);
  });

  it('a removed primitive comes back on undo; a preset re-frames on undo', () => {
    const state = run(
      [
        { type: 'load', params: { seed: 1 } },
        { type: 'change', volumes: [], key: null, now: 0 },
        { type: 'change', params: { seed: 7 }, key: null, frame: true, now: 1 },
      ],
      [sphere],
    );
    expect(state.frame).toBe(true);
    const presetUndone = editorReducer(state, { type: 'undo' });
    expect(presetUndone.frame).toBe(true);
    expect(presetUndone.params).toEqual({ seed: 1 });
    expect(editorReducer(presetUndone, { type: 'undo' }).volumes).toEqual([sphere]);
  });

  it('a stroke drawn over many moves is one undo step, recorded on release', () => {
    const point = (k: number): [number, number, number] => [2 + k / 10, 6, 0];
    const stroke = (n: number): Edit => ({
      op: 'paint',
      points: Array.from({ length: n }, (_, k) => point(k)),
      radius: 0.6,
      density: 400,
      segment: 0.25,
      kill: 0.4,
    });
    const cut: Edit = { op: 'cut', at: [1, 4, 0] };
    // Moves 1.5 s apart: no coalescing window could hold them; the draft is never recorded.
    const drawing = Array.from({ length: 30 }, (_, i): EditorAction => ({
      type: 'draft',
      edits: [cut, stroke(i + 1)],
    }));
    const state = run([
      { type: 'load', params: { seed: 1 } },
      { type: 'change', edits: [cut], key: null, now: 0 },
      ...drawing,
      { type: 'change', edits: [cut, stroke(30)], key: null, now: 45_000 },
    ]);
    expect(state.edits).toEqual([cut, stroke(30)]);
    expect(state.history?.past).toHaveLength(2);
    const strokeUndone = editorReducer(state, { type: 'undo' });
    expect(strokeUndone.edits).toEqual([cut]);
    const cutUndone = editorReducer(strokeUndone, { type: 'undo' });
    expect(cutUndone.edits).toEqual([]);
    expect(undoable(cutUndone)).toEqual({ canUndo: false, canRedo: true });
    const redone = editorReducer(editorReducer(cutUndone, { type: 'redo' }), { type: 'redo' });
    expect(redone.edits).toEqual([cut, stroke(30)]);
  });

  it('a draft cancelled (back to the list it started from) leaves no step; edits undo with params', () => {
    const cut: Edit = { op: 'cut', at: [1, 4, 0] };
    const bend: Edit = { op: 'bend', at: [2, 5, 0], to: [2.3, 4.6, 0] };
    const state = run([
      { type: 'load', params: { seed: 1 } },
      { type: 'draft', edits: [bend] },
      { type: 'change', edits: [], key: null, now: 10 },
    ]);
    expect(state.edits).toEqual([]);
    expect(undoable(state).canUndo).toBe(false);
    const mixed = run([
      { type: 'load', params: { seed: 1 } },
      { type: 'change', edits: [cut], key: null, now: 0 },
      { type: 'change', params: { seed: 2 }, key: 'seed', now: 5 },
      { type: 'change', edits: [cut, bend], key: null, now: 9 },
    ]);
    const once = editorReducer(mixed, { type: 'undo' });
    expect(once).toMatchObject({ params: { seed: 2 }, edits: [cut] });
    expect(editorReducer(once, { type: 'undo' })).toMatchObject({
      params: { seed: 1 },
      edits: [cut],
    });
  });

  it('the share link edits are there from the start, before the generator is ready', () => {
    const cut: Edit = { op: 'cut', at: [1, 4, 0] };
    const before = initialEditor([], [cut]);
    expect(editorReducer(before, { type: 'draft', edits: [] })).toBe(before);
    const loaded = editorReducer(before, { type: 'load', params: { seed: 1 } });
    expect(loaded.edits).toEqual([cut]);
    expect(loaded.history?.present.edits).toEqual([cut]);
  });
});
