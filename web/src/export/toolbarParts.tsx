/**
 * The toolbar's parts outside the export menu: the status line, the embed button and dialog,
 * and the file actions (PNG screenshot, preset JSON save and load).
 */
import { useEffect, useState, type RefObject } from 'react';
import type { Edit, Params, ParamSpec, VolumePrimitive } from 'sylva-trees/core';
import { EmbedDialog } from '../embed/EmbedDialog';
import { encodeEdits, encodeVolumes, MAX_EDITS_LINK_LENGTH } from 'sylva-trees/url';
import type { TreeViewer } from '../viewer/TreeViewer';
import { canvasPng, downloadBlob, readTextFile } from './download';
import { MAX_PRESET_FILE_BYTES, parsePresetFile, presetFileText } from './presetFile';

/** What the toolbar last did. */
export type Status = { kind: 'ok' | 'error' | 'busy'; text: string } | null;

/** The toolbar's status; a success clears itself after a few seconds. */
export function useToolbarStatus(): [Status, (status: Status) => void] {
  const [status, setStatus] = useState<Status>(null);
  useEffect(() => {
    if (status?.kind !== 'ok') return;
    const timer = setTimeout(() => setStatus(null), 6000);
    return () => clearTimeout(timer);
  }, [status]);
  return [status, setStatus];
}

/** The status line under the toolbar (an error can be dismissed). */
export function ToolbarStatus({ status, onDismiss }: { status: Status; onDismiss: () => void }) {
  if (!status) return null;
  return (
    <p
      className={`toolbar-status toolbar-status-${status.kind}`}
      role={status.kind === 'error' ? 'alert' : 'status'}
      data-testid="toolbar-status"
    >
      {status.text}
      {status.kind === 'error' ? (
        <button type="button" aria-label="Dismiss" onClick={onDismiss}>
          ×
        </button>
      ) : null}
    </p>
  );
}

/** The `e=` text of `edits` for an embed link: '' when none or too long for a link. */
export function linkEdits(edits: readonly Edit[]): string {
  const text = encodeEdits(edits);
  return text.length <= MAX_EDITS_LINK_LENGTH ? text : '';
}

/**
 * "Copy embed code": the dialog gets the volumes, hand edits and page URL as they were when it
 * opened. Edits too long for a link are left out, as the share link leaves them out.
 */
export function EmbedButton(props: {
  registry: readonly ParamSpec[];
  params: Params;
  volumesRef: RefObject<VolumePrimitive[]>;
  editsRef: RefObject<Edit[]>;
}) {
  const [embedAt, setEmbedAt] = useState<{
    volumes: string;
    edits: string;
    appHref: string;
  } | null>(null);
  const { registry, params, volumesRef, editsRef } = props;
  return (
    <>
      <button
        type="button"
        data-testid="copy-embed"
        onClick={() =>
          setEmbedAt({
            volumes: encodeVolumes(volumesRef.current ?? []),
            edits: linkEdits(editsRef.current ?? []),
            appHref: window.location.href,
          })
        }
      >
        Copy embed code
      </button>
      {embedAt ? (
        <EmbedDialog input={{ registry, params, ...embedAt }} onClose={() => setEmbedAt(null)} />
      ) : null}
    </>
  );
}

/** Saves the viewer's current frame as `<baseName>.png`. */
export function saveScreenshot(viewer: TreeViewer, baseName: string, report: (s: Status) => void) {
  canvasPng(viewer.overlayHost().domElement, () => viewer.renderNow()).then(
    (blob) => {
      downloadBlob(blob, `${baseName}.png`);
      report({ kind: 'ok', text: `Saved ${baseName}.png.` });
    },
    (error: unknown) => report({ kind: 'error', text: String(error) }),
  );
}

/** Saves every parameter value as `<baseName>.json`. */
export function savePresetFile(
  registry: readonly ParamSpec[],
  params: Params,
  baseName: string,
  report: (s: Status) => void,
): void {
  const name = `${baseName}.json`;
  const text = presetFileText(registry, params);
  downloadBlob(new Blob([text], { type: 'application/json' }), name);
  report({ kind: 'ok', text: `Saved ${name}.` });
}

/** Reads a preset file; its params go to `onLoad` (the same validation as a share link). */
export function loadPresetFile(
  file: File,
  registry: readonly ParamSpec[],
  onLoad: (params: Params) => void,
  report: (s: Status) => void,
): void {
  readTextFile(file, MAX_PRESET_FILE_BYTES)
    .then((text) => {
      const result = parsePresetFile(registry, text);
      if (!result.ok) {
        report({ kind: 'error', text: `Could not load "${file.name}": ${result.error}` });
        return;
      }
      onLoad(result.params);
      report({ kind: 'ok', text: [`Loaded ${file.name}.`, ...result.messages].join(' ') });
    })
    .catch((error: unknown) => {
      const message = error instanceof Error ? error.message : String(error);
      report({ kind: 'error', text: `Could not load "${file.name}": ${message}` });
    });
}
