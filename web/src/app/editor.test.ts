/** The editor's reducer: params and growth volumes share one undo history. */
import { describe, expect, it } from 'vitest';
import type { VolumePrimitive } from 'sylva-trees/core';
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
});
