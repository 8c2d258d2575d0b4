/**
 * The hand-edit tools' React side: the active tool and its brush, the tools in the viewer
 * (`HandEditTools`), keyboard shortcuts (P paint, O crown outline, C cut, B bend, Escape: no tool),
 * which edits the tree meta reports unresolved, the share URL's `e=` (left out, with a message,
 * when the history is too long for a link) and the JSON export and import. The edit list itself
 * lives in the editor's reducer: a drag is a `draft` while drawn and one `change` on release.
 */
import { useCallback, useEffect, useRef, useState, type RefObject } from 'react';
import {
  DEFAULT_BRUSH,
  editsDocument,
  EditsError,
  parseEditsDocument,
  quantizeEdit,
  type Edit,
  type EditReport,
  type Params,
} from 'sylva-trees/core';
import { decodeEdits, EDITS_KEY, encodeEdits, MAX_EDITS_LINK_LENGTH } from 'sylva-trees/url';
import { HandEditTools, type Brush, type EditTool } from '../viewer/HandEditTools';
import type { TreeViewer } from '../viewer/TreeViewer';
import { installDebugHook } from './debugHook';
import type { Editor } from './useEditor';
import type { Generator } from './useGenerator';
import { withQueryEntry } from './queryEntry';

/** What the edit panel sees. */
export interface HandEdits {
  tool: EditTool | null;
  setTool: (tool: EditTool | null) => void;
  brush: Brush;
  setBrush: (brush: Brush) => void;
  edits: Edit[];
  /** The tree meta's report per edit (empty until a core that reports edits). */
  reports: EditReport[];
  remove: (index: number) => void;
  clear: () => void;
  /** The JSON document of the edits (`sylva-edits.json`). */
  exportText: () => string;
  /** Reads a document; a bad one is reported (`onNotice`) and changes nothing. */
  importText: (text: string) => void;
  /** The file could not be read: reported like a bad document. */
  importFailed: (why: string) => void;
  /** The share link leaves the edits out (too long): the message to show, else null. */
  linkNotice: string | null;
}

/** Keyboard shortcuts of the tools. */
export const TOOL_KEYS: Record<string, EditTool> = { p: 'paint', o: 'crown', c: 'cut', b: 'bend' };

/**
 * `list` with a new `edit` at its end; a crown outline replaces the crown edit before it (one
 * drawn crown per tree).
 */
export function appendEdit(list: readonly Edit[], edit: Edit): Edit[] {
  const kept = edit.op === 'crown' ? list.filter((e) => e.op !== 'crown') : list;
  return [...kept, edit];
}

/** The `e=` edits of a page query, with a notice if they were ignored. */
export function editsFromSearch(search: string): { edits: Edit[]; messages: string[] } {
  return decodeEdits(new URLSearchParams(search).get(EDITS_KEY));
}

/** The page URL's `e=` edits, with a notice if they were ignored. */
export function editsFromUrl(): { edits: Edit[]; messages: string[] } {
  return editsFromSearch(window.location.search);
}

/** The `e=` text for `edits`, or null when it is too long for a link. */
export function linkText(edits: readonly Edit[]): string | null {
  const text = encodeEdits(edits);
  return text.length <= MAX_EDITS_LINK_LENGTH ? text : null;
}

function writeEditsToUrl(text: string): void {
  const current = window.location.search;
  const search = withQueryEntry(current, EDITS_KEY, text);
  if (search !== current) {
    const url = `${window.location.pathname}${search}${window.location.hash}`;
    window.history.replaceState(window.history.state, '', url);
  }
}

/** Whether a key press belongs to a text field (no tool shortcuts there). */
function typing(event: KeyboardEvent): boolean {
  const t = event.target;
  return (
    t instanceof HTMLElement && (t.isContentEditable || /^(INPUT|SELECT|TEXTAREA)$/.test(t.tagName))
  );
}

/**
 * `edit` as made now: a cut carries the tree's Age as its year, so a younger tree still has the
 * branch and an older one grows woundwood over the face (a callus ring a year).
 */
export function dateEdit(edit: Edit, params: Params | null): Edit {
  const age = params?.age;
  if (edit.op !== 'cut' || edit.year !== undefined || age === undefined) return edit;
  return quantizeEdit({ ...edit, year: age });
}

/** What the tools' callbacks read at the time they run. */
interface Latest {
  editor: Editor;
  onNotice: (text: string) => void;
}

/**
 * The tools in the viewer, wired to the editor (a drag is a draft on top of the list it began
 * with, then one change), the meta's per-edit reports, and the debug hook. Returns the tools.
 */
function useToolsInViewer(
  viewerRef: RefObject<TreeViewer | null>,
  latest: RefObject<Latest>,
  setReports: (reports: EditReport[]) => void,
): RefObject<HandEditTools | null> {
  const toolsRef = useRef<HandEditTools | null>(null);
  useEffect(() => {
    const viewer = viewerRef.current;
    if (!viewer) return;
    const host = viewer.overlayHost();
    /** The list before the drag began, for its draft and its commit. */
    let base: Edit[] | null = null;
    const start = () => (base ??= latest.current.editor.editsRef.current ?? []);
    const dated = (edit: Edit) => dateEdit(edit, latest.current.editor.paramsRef.current);
    const tools = new HandEditTools(host, {
      draft: (edit) => latest.current.editor.draft(appendEdit(start(), dated(edit))),
      commit: (edit) => {
        const list = appendEdit(start(), dated(edit));
        base = null;
        // Interactive: a cut answers with a quick preview; the release settles to the full tree.
        latest.current.editor.change({ edits: list, key: null }, true);
      },
      cancel: () => {
        if (base !== null) latest.current.editor.change({ edits: base, key: null });
        base = null;
      },
      notice: (text) => latest.current.onNotice(text),
    });
    toolsRef.current = tools;
    let bounds: { min: number[]; max: number[] } | null = null;
    const unsubscribe = host.onTree((buffers) => {
      bounds = buffers.meta.bounds;
      setReports(buffers.meta.edits ?? []);
    });
    const uninstall = installDebugHook({
      edits: () => ({
        tool: tools.active,
        dragging: tools.dragging,
        strokePoints: tools.strokePoints,
        count: latest.current.editor.editsRef.current?.length ?? 0,
        bounds,
      }),
      pickBark: (x, y) => tools.pick(x, y),
      project: (p) => tools.project(p),
    });
    return () => {
      uninstall();
      unsubscribe();
      tools.dispose();
      if (toolsRef.current === tools) toolsRef.current = null;
    };
  }, [viewerRef, latest, setReports]);
  return toolsRef;
}

/**
 * See the module comment. `onNotice` shows a message in the app's banner; `generatorRef`'s worker
 * bakes the cut faces' end grain as soon as the Cut tool is chosen.
 */
export function useHandEdits(
  viewerRef: RefObject<TreeViewer | null>,
  editor: Editor,
  onNotice: (text: string) => void,
  generatorRef?: RefObject<Generator | null>,
): HandEdits {
  const [tool, setTool] = useState<EditTool | null>(null);
  const [brush, setBrush] = useState<Brush>({ ...DEFAULT_BRUSH });
  const [reports, setReports] = useState<EditReport[]>([]);
  const latest = useRef<Latest>({ editor, onNotice });
  useEffect(() => {
    latest.current = { editor, onNotice };
  });
  const { edits } = editor.state;

  const toolsRef = useToolsInViewer(viewerRef, latest, setReports);

  useEffect(() => toolsRef.current?.set(tool, brush), [toolsRef, tool, brush]);
  // The Cut tool chosen (or the bark type changed while it is): the worker bakes the end grain
  // while the user aims, not at the first cut.
  const barkType = editor.state.params?.bark_type;
  useEffect(() => {
    if (tool === 'cut') generatorRef?.current?.prepareCut();
  }, [tool, barkType, generatorRef]);

  useEffect(() => {
    const onKey = (event: KeyboardEvent) => {
      if (event.ctrlKey || event.metaKey || event.altKey || typing(event)) return;
      if (event.key === 'Escape' && !toolsRef.current?.dragging) setTool(null);
      const chosen = TOOL_KEYS[event.key.toLowerCase()];
      if (chosen) setTool((current) => (current === chosen ? null : chosen));
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [toolsRef]);

  // The share URL follows the edits (debounced like the params); too long: no `e=` at all.
  const text = linkText(edits);
  useEffect(() => {
    const timer = setTimeout(() => writeEditsToUrl(text ?? ''), 300);
    return () => clearTimeout(timer);
  }, [text]);
  const linkNotice =
    text === null
      ? `The share link leaves the edits out: they take ${encodeEdits(edits).length} characters, more than its ${MAX_EDITS_LINK_LENGTH}. Use “Export edits…” to keep them.`
      : null;

  const remove = useCallback((index: number) => {
    const current = latest.current.editor.editsRef.current ?? [];
    latest.current.editor.change({ edits: current.filter((_, i) => i !== index), key: null });
  }, []);
  const clear = useCallback(() => latest.current.editor.change({ edits: [], key: null }), []);
  const exportText = useCallback(
    () => editsDocument(latest.current.editor.editsRef.current ?? []),
    [],
  );
  const importFailed = useCallback((why: string) => {
    latest.current.onNotice(`Could not import the edits (the tree and its edits are kept): ${why}`);
  }, []);
  const importText = useCallback(
    (json: string) => {
      try {
        const list = parseEditsDocument(json).map(quantizeEdit);
        latest.current.editor.change({ edits: list, key: null });
      } catch (error) {
        if (!(error instanceof EditsError)) throw error;
        importFailed(error.message);
      }
    },
    [importFailed],
  );

  // Edits of another tree may report nothing yet: only as many reports as edits count.
  const shown = reports.length === edits.length ? reports : [];
  return {
    tool,
    setTool,
    brush,
    setBrush,
    edits,
    reports: shown,
    remove,
    clear,
    exportText,
    importText,
    importFailed,
    linkNotice,
  };
}
