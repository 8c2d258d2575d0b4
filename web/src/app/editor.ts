/**
 * The editor's one reducer (plain module, no React): the parameters, the growth volumes and their
 * undo/redo history live in one state, so a volume edit undoes like a slider. The app shows each
 * new state (a generation request, the URL, the overlay); nothing else holds a copy.
 */
import type { Params, VolumePrimitive } from 'sylva-trees/core';
import { canRedo, canUndo, record, redo, startHistory, undo, type History } from './history';

/** Everything the user edits. */
export interface EditorState {
  /** The current params; null until the generator is ready (the registry gives the defaults). */
  params: Params | null;
  /** The growth volumes (from the share link's `vol=` at first). */
  volumes: VolumePrimitive[];
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
      key: string | null;
      frame?: boolean;
      now: number;
    }
  | { type: 'undo' }
  | { type: 'redo' };

/** The state before the generator is ready. */
export function initialEditor(volumes: VolumePrimitive[]): EditorState {
  return { params: null, volumes, history: null, frame: false };
}

/** The editor's transitions (pure). */
export function editorReducer(state: EditorState, action: EditorAction): EditorState {
  switch (action.type) {
    case 'load': {
      const history = startHistory({ params: action.params, volumes: state.volumes });
      return { params: action.params, volumes: state.volumes, history, frame: false };
    }
    case 'change': {
      if (state.history === null || state.params === null) return state;
      const params = action.params ?? state.params;
      const volumes = action.volumes ?? state.volumes;
      const frame = action.frame ?? false;
      const history = record(state.history, { params, volumes }, { ...action, frame });
      return { params, volumes, history, frame };
    }
    case 'undo':
    case 'redo': {
      if (state.history === null) return state;
      const step = action.type === 'undo' ? undo(state.history) : redo(state.history);
      if (step === null) return state;
      const { params, volumes, frame } = step.shown;
      return { params, volumes, history: step.history, frame };
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
