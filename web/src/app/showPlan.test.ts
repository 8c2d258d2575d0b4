/** Which editor changes ask for a tree, and what the request carries (volumes, edits, preview). */
import { describe, expect, it } from 'vitest';
import type { Edit } from 'sylva-trees/core';
import { realRegistry } from 'sylva-trees/testing';
import { planShow } from './appEffects';
import { editorReducer, initialEditor, type EditorState } from './editor';

const registry = realRegistry();
const loaded = (): EditorState =>
  editorReducer(initialEditor([]), { type: 'load', params: { seed: 1, show_preview: 0 } });
const cut: Edit = { op: 'cut', at: [1, 4, 0] };
const stroke: Edit = {
  op: 'paint',
  points: [[2, 6, 0]],
  radius: 0.6,
  density: 400,
  segment: 0.25,
  kill: 0.4,
};

describe('planShow', () => {
  it('an edit is a skeleton change: the request carries the whole list', () => {
    const before = loaded();
    const after = editorReducer(before, { type: 'change', edits: [cut], key: null, now: 0 });
    expect(planShow(registry, before, after, false)).toEqual({
      request: { volumes: [], edits: [cut], interactive: false },
      viewer: false,
    });
    // Undo is a change of the list too.
    const undone = editorReducer(after, { type: 'undo' });
    expect(planShow(registry, after, undone, false).request?.edits).toEqual([]);
  });

  it('a stroke being drawn asks for previews, its release for the full tree', () => {
    const before = loaded();
    const drawing = editorReducer(before, { type: 'draft', edits: [stroke] });
    expect(planShow(registry, before, drawing, true).request).toEqual({
      volumes: [],
      edits: [stroke],
      interactive: true,
    });
    const done = editorReducer(drawing, { type: 'change', edits: [stroke], key: null, now: 5 });
    expect(planShow(registry, drawing, done, false).request?.interactive).toBe(false);
  });

  it('a viewer-only parameter regenerates nothing; params keep the edits in the request', () => {
    const before = editorReducer(loaded(), { type: 'change', edits: [cut], key: null, now: 0 });
    const preview = editorReducer(before, {
      type: 'change',
      params: { seed: 1, show_preview: 1 },
      key: 'show_preview',
      now: 9,
    });
    expect(planShow(registry, before, preview, false)).toEqual({ request: null, viewer: true });
    const reseeded = editorReducer(before, {
      type: 'change',
      params: { seed: 2, show_preview: 0 },
      key: 'seed',
      now: 9,
    });
    expect(planShow(registry, before, reseeded, true).request).toEqual({
      volumes: [],
      edits: [cut],
      interactive: true,
    });
  });
});
