/**
 * The editor's one reducer (plain module, no React): the parameters, the growth volumes, the hand
 * edit list and their undo/redo history live in one state, so a volume edit or a cut undoes like a
 * slider. A stroke or a bend being drawn is a `draft` (shown, not recorded); releasing the
 * pointer records it as one step. The app shows each new state (a generation request, the URL,
 * the overlay); nothing else holds a copy.
 */
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';
import { canRedo, canUndo, record, redo, startHistory, undo, type History } from './history';

/** Everything the user edits. */
export interface EditorState {
  /** The current params; null until the generator is ready (the registry gives the defaults). */
  params: Params | null;
  /** The growth volumes (from the share link's `vol=` at first). */
  volumes: VolumePrimitive[];
  /** The hand edit list (from the share link's `e=` at first). */
  edits: Edit[];
  /** Undo/redo; null until loaded. */
  history: History | null;
  /** The change that made this state asks to re-frame the camera (a preset, Reset, its undo). */
  frame: boolean;
}

/** What changes the editor. */
export type EditorAction =
  /** The generator is ready: the initial params, with nothing to undo. */
  | { type: 'load'; params: Params }
  /**
   * An edit of the params and/or the volumes; `key` names a continuous edit (a param id,
   * `volume:<index>`: coalesced into one undo step), null a discrete step.
   */
  | {
      type: 'change';
      params?: Params;
      volumes?: VolumePrimitive[];
      edits?: Edit[];
      key: string | null;
      frame?: boolean;
      now: number;
    }
  /**
   * The edit list while a stroke or a bend is drawn: shown (an interactive request) but not
   * recorded; the `change` on release records the whole stroke as one step.
   */
  | { type: 'draft'; edits: Edit[] }
  | { type: 'undo' }
  | { type: 'redo' };

/** The state before the generator is ready. */
export function initialEditor(volumes: VolumePrimitive[], edits: Edit[] = []): EditorState {
  return { params: null, volumes, edits, history: null, frame: false };
}

/** The editor's transitions (pure). */
export function editorReducer(state: EditorState, action: EditorAction): EditorState {
  switch (action.type) {
    case 'load': {
      const { volumes, edits } = state;
      const history = startHistory({ params: action.params, volumes, edits });
      return { params: action.params, volumes, edits, history, frame: false };
    }
    case 'change': {
      if (state.history === null || state.params === null) return state;
      const params = action.params ?? state.params;
      const volumes = action.volumes ?? state.volumes;
      const edits = action.edits ?? state.edits;
      const frame = action.frame ?? false;
      const history = record(state.history, { params, volumes, edits }, { ...action, frame });
      return { params, volumes, edits, history, frame };
    }
    case 'draft': {
      if (state.history === null || state.params === null) return state;
      return { ...state, edits: action.edits, frame: false };
    }
    case 'undo':
    case 'redo': {
      if (state.history === null) return state;
      const step = action.type === 'undo' ? undo(state.history) : redo(state.history);
      if (step === null) return state;
      const { params, volumes, edits, frame } = step.shown;
      return { params, volumes, edits, history: step.history, frame };
    }
    default: {
      const unknown: never = action;
      throw new Error(`unknown editor action ${JSON.stringify(unknown)}`);
    }
  }
}

/** Whether there is a step to undo / redo. */
export function undoable(state: EditorState): { canUndo: boolean; canRedo: boolean } {
  const h = state.history;
  return { canUndo: h !== null && canUndo(h), canRedo: h !== null && canRedo(h) };
}
