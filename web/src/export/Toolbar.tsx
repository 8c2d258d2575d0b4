/**
 * The viewer toolbar: Export menu (PNG screenshot, preset JSON save/load and, when the core has
 * exporters, a GLB for engines, a GLB for editors, a GLB for strict importers, a zipped OBJ, the
 * GLB with the growth animation and a zip of one GLB per year, each with a line saying when to
 * choose it), "Copy embed code" and a link to the docs page.
 */
import { useCallback, useEffect, useRef, useState, type RefObject } from 'react';
import type { Edit, Params, ParamSpec, VolumePrimitive } from 'sylva-trees/core';
import { createModuleWorker } from '../createWorker';
import { useDismiss } from '../ui/useDismiss';
import type { TreeViewer } from '../viewer/TreeViewer';
import { downloadBlob } from './download';
import {
  ExportClient,
  type ExportFormat,
  type ExportResponse,
  type LeafExport,
} from 'sylva-trees/worker';
import { presetFileName } from './presetFile';
import {
  EmbedButton,
  loadPresetFile,
  savePresetFile,
  saveScreenshot,
  ToolbarStatus,
  useToolbarStatus,
  type Status,
} from './toolbarParts';
import './toolbar.css';

interface Props {
  registry: readonly ParamSpec[];
  params: Params;
  /** The preset the params match, for file names. */
  presetName: string | null;
  viewerRef: RefObject<TreeViewer | null>;
  /** The growth volume primitives sent with every request. */
  volumesRef: RefObject<VolumePrimitive[]>;
  /** The hand edits: an export is the edited tree. */
  editsRef: RefObject<Edit[]>;
  /** Applies params read from a preset file (one undoable step). */
  onLoadParams: (params: Params) => void;
}

/** A mesh download of the Export menu. */
interface MeshExport {
  testId: string;
  format: ExportFormat;
  /** GLB: how the leaves are written (the core's default: instanced). */
  leaves?: LeafExport;
  /** GLB: no glTF extension (the core's `strict` option), for Godot and strict importers. */
  strict?: boolean;
  label: string;
  /** One line: when to choose it. */
  hint: string;
}

/** The mesh downloads, in menu order (docs/formats.md says which to choose for which tool). */
export const MESH_EXPORTS: readonly MeshExport[] = [
  {
    testId: 'export-glb',
    format: 'glb',
    leaves: 'instanced',
    label: 'GLB for engines (instanced leaves)',
    hint: 'For three.js and Unity (glTFast): one leaf mesh drawn once per leaf, the lightest file.',
  },
  {
    testId: 'export-glb-baked',
    format: 'glb',
    leaves: 'baked',
    label: 'GLB for Blender and other editors (leaves merged into one mesh)',
    hint: 'For Blender, Unreal and other editors, which would make one object per instanced leaf.',
  },
  {
    testId: 'export-glb-strict',
    format: 'glb',
    strict: true,
    label: 'GLB for Godot and strict importers',
    hint: 'No glTF extension required: float normals, leaves merged; a larger file.',
  },
  {
    testId: 'export-obj',
    format: 'obj',
    label: 'OBJ + MTL + textures (zip)',
    hint: 'For tools without glTF (and Godot): leaves merged, no wind data.',
  },
  {
    testId: 'export-glb-growth',
    format: 'glb-growth',
    label: 'GLB with growth animation',
    hint: 'The tree growing from year 0 to its Age (one second a year): morph targets, leaves merged; plays in Blender and three.js.',
  },
  {
    testId: 'export-glb-years',
    format: 'glb-years',
    label: 'GLB per year (zip)',
    hint: 'For tools without glTF animation: the tree at every whole year up to its Age, one GLB each.',
  },
];

/** Downloads an export's one file: the GLB, or the ZIP of the OBJ, its MTL and its textures. */
function saveExported(response: ExportResponse, format: ExportFormat, report: (s: Status) => void) {
  const [file] = response.files;
  if (!file) throw new Error('the exporter returned no file');
  const blob = 'blob' in file ? file.blob : new Blob([file.bytes as BlobPart], { type: file.mime });
  downloadBlob(blob, file.name);
  const contents =
    format === 'obj' ? ' (OBJ, MTL and textures)' : format === 'glb-years' ? ' (a GLB per year)' : '';
  report({ kind: 'ok', text: `Saved ${file.name}${contents}.` });
}

/** A mesh download of the menu, disabled (with the reason) while the core lacks its format. */
function MeshExportButton(props: {
  item: MeshExport;
  formats: ExportFormat[] | 'checking' | null;
  onExport: () => void;
}) {
  const { item, formats } = props;
  const available = Array.isArray(formats) && formats.includes(item.format);
  return (
    <button
      type="button"
      className="toolbar-item-hinted"
      data-testid={item.testId}
      disabled={!available}
      title={
        available
          ? undefined
          : formats === 'checking'
            ? 'Checking the core…'
            : 'This build of the Sylva core has no exporter for this format yet'
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
  const { registry, params, presetName, viewerRef, volumesRef, editsRef, onLoadParams } = props;
  const menuRef = useRef<HTMLDetailsElement>(null);
  const fileRef = useRef<HTMLInputElement>(null);
  const clientRef = useRef<ExportClient | null>(null);
  const [formats, setFormats] = useState<ExportFormat[] | 'checking' | null>(null);
  const [status, setStatus] = useToolbarStatus();

  useEffect(() => () => clientRef.current?.dispose(), []);

  const client = useCallback((): ExportClient => {
    clientRef.current ??= new ExportClient(createModuleWorker);
    return clientRef.current;
  }, []);

  const closeMenu = () => {
    if (menuRef.current) menuRef.current.open = false;
  };

  const baseName = presetFileName(params, presetName).replace(/\.json$/, '');

  const onToggle = () => {
    if (!menuRef.current?.open || formats !== null) return;
    setFormats('checking');
    client()
      .formats()
      .then(setFormats, () => setFormats([]));
  };

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

  const exportMesh = ({ format, leaves, strict, label }: MeshExport) => {
    closeMenu();
    setStatus({ kind: 'busy', text: `Exporting ${label}…` });
    client()
      .export(params, volumesRef.current ?? [], format, {
        name: baseName,
        edits: editsRef.current ?? [],
        ...(leaves ? { leaves } : {}),
        ...(strict ? { strict } : {}),
      })
      .then((response) => saveExported(response, format, setStatus))
      .catch((error: unknown) => {
        const message = error instanceof Error ? error.message : String(error);
        setStatus({ kind: 'error', text: `Export failed: ${message}` });
      });
  };

  return (
    <div className="toolbar" data-testid="toolbar">
      <details className="toolbar-menu" ref={menuRef} onToggle={onToggle}>
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
              formats={formats}
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
          if (file) loadPresetFile(file, registry, onLoadParams, setStatus);
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
