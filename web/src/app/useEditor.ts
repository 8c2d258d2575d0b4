/**
 * React side of the editor's reducer (`editor.ts`): the state, live views of it for code that
 * runs outside a render (the generator's first request, exports, LODs), and the history's
 * buttons and keyboard shortcuts. Each new state is shown (`show`) before React renders it, so
 * the worker already runs while the panel re-renders.
 */
import { useCallback, useEffect, useMemo, useRef, useState, type RefObject } from 'react';
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';
import {
  editorReducer,
  initialEditor,
  undoable,
  type EditorAction,
  type EditorState,
} from './editor';
import { historyShortcut } from './history';

/** An edit as the controls make it (see the reducer's `change`). */
export interface EditorChange {
  params?: Params;
  volumes?: VolumePrimitive[];
  edits?: Edit[];
  key: string | null;
  frame?: boolean;
}

/** What the app sees of the editor. */
export interface Editor {
  state: EditorState;
  /** The current params (null before ready), read outside a render. */
  paramsRef: RefObject<Params | null>;
  /** The current growth volumes, read outside a render. */
  volumesRef: RefObject<VolumePrimitive[]>;
  /** The current hand edits, read outside a render. */
  editsRef: RefObject<Edit[]>;
  canUndo: boolean;
  canRedo: boolean;
  /** The generator is ready with these params (shown by the generator's first request). */
  load: (params: Params) => void;
  /** Applies and records an edit; `interactive` while a control is dragged or typed into. */
  change: (change: EditorChange, interactive?: boolean) => void;
  /** Shows the edit list of a stroke being drawn (an interactive request; not recorded). */
  draft: (edits: Edit[]) => void;
  undo: () => void;
  redo: () => void;
}

/** Shows a new state: `previous` is the state before it. */
export type ShowState = (previous: EditorState, next: EditorState, interactive: boolean) => void;

/** See the module docs. `initialVolumes`, `initialEdits`: the share link's primitives and edits. */
export function useEditor(
  initialVolumes: VolumePrimitive[],
  initialEdits: Edit[],
  show: ShowState,
): Editor {
  const [initial] = useState(() => initialEditor(initialVolumes, initialEdits));
  const [state, setState] = useState(initial);
  const stateRef = useRef(initial);
  const showRef = useRef(show);
  useEffect(() => {
    showRef.current = show;
  });

  const dispatch = useCallback((action: EditorAction, interactive = false, visible = true) => {
    const previous = stateRef.current;
    const next = editorReducer(previous, action);
    if (next === previous) return;
    stateRef.current = next;
    if (visible) showRef.current(previous, next, interactive);
    setState(next);
  }, []);

  const load = useCallback(
    (params: Params) => dispatch({ type: 'load', params }, false, false),
    [dispatch],
  );
  const change = useCallback(
    (edit: EditorChange, interactive = false) =>
      dispatch({ type: 'change', ...edit, now: performance.now() }, interactive),
    [dispatch],
  );
  const draft = useCallback(
    (edits: Edit[]) => dispatch({ type: 'draft', edits }, true),
    [dispatch],
  );
  const undo = useCallback(() => dispatch({ type: 'undo' }), [dispatch]);
  const redo = useCallback(() => dispatch({ type: 'redo' }), [dispatch]);

  // Ctrl+Z / Ctrl+Shift+Z / Ctrl+Y (⌘ on macOS), wherever the focus is: the number fields commit
  // every valid keystroke, so undo also covers typing.
  useEffect(() => {
    const onKeyDown = (event: KeyboardEvent) => {
      const action = historyShortcut(event);
      if (action === null || stateRef.current.history === null) return;
      event.preventDefault();
      dispatch({ type: action });
    };
    window.addEventListener('keydown', onKeyDown);
    return () => window.removeEventListener('keydown', onKeyDown);
  }, [dispatch]);

  const views = useMemo(
    () => ({
      paramsRef: {
        get current() {
          return stateRef.current.params;
        },
      },
      volumesRef: {
        get current() {
          return stateRef.current.volumes;
        },
      },
      editsRef: {
        get current() {
          return stateRef.current.edits;
        },
      },
    }),
    [],
  );

  return { state, ...views, ...undoable(state), load, change, draft, undo, redo };
}
