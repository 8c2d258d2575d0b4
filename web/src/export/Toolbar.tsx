/**
 * The viewer toolbar: Export menu (PNG screenshot, preset JSON save/load and, when the core has
 * exporters, a GLB for engines, a GLB for editors, a GLB for strict importers, a zipped OBJ, the
 * GLB with the growth animation, a zip of one GLB per year and the zipped levels of detail with
 * the impostor, each with a line saying when to choose it), "Copy embed code" and a link to the
 * docs page.
 */
import { useRef, type RefObject } from 'react';
import type { Edit, Params, ParamSpec, VolumePrimitive } from 'sylva-trees/core';
import { useDismiss } from '../ui/useDismiss';
import type { TreeViewer } from '../viewer/TreeViewer';
import type { LodController } from '../lod/LodController';
import type { ExportFormat } from 'sylva-trees/worker';
import type { Exporter } from '../pool/generationPool';
import { MESH_EXPORTS, runMeshExport, saveExported, type MeshExport } from './meshExport';
import { presetFileName } from './presetFile';
import {
  EmbedButton,
  loadPresetFile,
  savePresetFile,
  saveScreenshot,
  ToolbarStatus,
  useToolbarStatus,
} from './toolbarParts';
import './toolbar.css';

interface Props {
  registry: readonly ParamSpec[];
  params: Params;
  /** The preset the params match, for file names. */
  presetName: string | null;
  viewerRef: RefObject<TreeViewer | null>;
  /** The LOD view's controller (the LOD zip's impostor is its atlas). */
  lodRef: RefObject<LodController | null>;
  /** The core's version (the impostor GLB's `asset.generator`). */
  version: string;
  /** The formats the core can export (the generator's `ready` message; every worker runs the same core). */
  exportFormats: readonly ExportFormat[];
  /** Runs the mesh exports: the app's generation pool, never the editor's worker. */
  exporter: Exporter;
  /** The growth volume primitives sent with every request. */
  volumesRef: RefObject<VolumePrimitive[]>;
  /** The hand edits: an export is the edited tree. */
  editsRef: RefObject<Edit[]>;
  /** Applies params read from a preset file (one undoable step). */
  onLoadParams: (params: Params) => void;
}

/** A mesh download of the menu, disabled (with the reason) while the core lacks its format. */
function MeshExportButton(props: {
  item: MeshExport;
  formats: readonly ExportFormat[];
  onExport: () => void;
}) {
  const { item, formats } = props;
  const available = formats.includes(item.format);
  return (
    <button
      type="button"
      className="toolbar-item-hinted"
      data-testid={item.testId}
      disabled={!available}
      title={
        available ? undefined : 'This build of the Sylva core has no exporter for this format yet'
      }
      onClick={props.onExport}
    >
      {item.label}
      <span className="toolbar-hint" data-testid={`${item.testId}-hint`}>
        {item.hint}
      </span>
    </button>
  );
}

/** Toolbar over the viewer (top right). */
export function Toolbar(props: Props) {
  const { registry, params, presetName, viewerRef, lodRef, volumesRef, editsRef } = props;
  const menuRef = useRef<HTMLDetailsElement>(null);
  const fileRef = useRef<HTMLInputElement>(null);
  const [status, setStatus] = useToolbarStatus();

  const closeMenu = () => {
    if (menuRef.current) menuRef.current.open = false;
  };

  const baseName = presetFileName(params, presetName).replace(/\.json$/, '');

  // Escape or a press outside closes the menu.
  useDismiss(menuRef);

  const screenshot = () => {
    closeMenu();
    const viewer = viewerRef.current;
    if (viewer) saveScreenshot(viewer, baseName, setStatus);
  };

  const savePreset = () => {
    closeMenu();
    savePresetFile(registry, params, baseName, setStatus);
  };

  const exportMesh = (item: MeshExport) => {
    closeMenu();
    setStatus({ kind: 'busy', text: `Exporting ${item.label}…` });
    const source = {
      params,
      volumes: volumesRef.current ?? [],
      edits: editsRef.current ?? [],
      name: baseName,
      lod: lodRef.current,
      generator: `Sylva ${props.version}`,
    };
    runMeshExport(props.exporter, item, source)
      .then((response) => saveExported(response, item.format, setStatus))
      .catch((error: unknown) => {
        const message = error instanceof Error ? error.message : String(error);
        setStatus({ kind: 'error', text: `Export failed: ${message}` });
      });
  };

  return (
    <div className="toolbar" data-testid="toolbar">
      <details className="toolbar-menu" ref={menuRef}>
        <summary data-testid="export-menu">Export</summary>
        <div className="toolbar-items" role="group" aria-label="Export">
          <button type="button" data-testid="export-png" onClick={screenshot}>
            PNG screenshot
          </button>
          <button type="button" data-testid="export-preset-save" onClick={savePreset}>
            Save preset JSON
          </button>
          <button
            type="button"
            data-testid="export-preset-load"
            onClick={() => {
              closeMenu();
              fileRef.current?.click();
            }}
          >
            Load preset JSON…
          </button>
          {MESH_EXPORTS.map((item) => (
            <MeshExportButton
              key={item.testId}
              item={item}
              formats={props.exportFormats}
              onExport={() => exportMesh(item)}
            />
          ))}
        </div>
      </details>
      <input
        ref={fileRef}
        type="file"
        accept=".json,application/json"
        hidden
        data-testid="preset-file-input"
        onChange={(e) => {
          const file = e.currentTarget.files?.[0];
          e.currentTarget.value = '';
          if (file) loadPresetFile(file, registry, props.onLoadParams, setStatus);
        }}
      />
      <EmbedButton {...{ registry, params, volumesRef, editsRef }} />
      <a
        className="toolbar-link"
        href="docs.html"
        target="_blank"
        rel="noopener"
        data-testid="docs-link"
      >
        Docs
      </a>
      <ToolbarStatus status={status} onDismiss={() => setStatus(null)} />
    </div>
  );
}
