/**
 * The mesh downloads of the Export menu (docs/formats.md says which to choose for which tool):
 * what each item asks for, and one export run in the app's generation pool (a pool worker, never
 * the editor's): the LOD zip first takes the impostor from the LOD view (`lod/impostorExport.ts`),
 * then the worker zips it with the levels.
 */
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';
import type { ExportFormat, ExportResponse, LeafExport } from 'sylva-trees/worker';
import { impostorFile } from '../lod/impostorExport';
import type { LodController } from '../lod/LodController';
import type { Exporter } from '../pool/generationPool';
import { downloadBlob } from './download';
import type { Status } from './toolbarParts';

/** A mesh download of the Export menu. */
export interface MeshExport {
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
  {
    testId: 'export-lods',
    format: 'lods',
    leaves: 'instanced',
    label: 'LODs + impostor (zip of 4 GLBs)',
    hint: 'LOD0, LOD1, LOD2 and the impostor (crossed quads on its atlas), as the GLB for engines.',
  },
  {
    testId: 'export-lods-strict',
    format: 'lods',
    strict: true,
    label: 'LODs + impostor, strict (zip of 4 GLBs)',
    hint: 'The same with no glTF extension, leaves merged: for Godot, Unreal and Blender.',
  },
];

/** What a downloaded ZIP holds, for the status line. */
const CONTENTS: Partial<Record<ExportFormat, string>> = {
  obj: ' (OBJ, MTL and textures)',
  'glb-years': ' (a GLB per year)',
  lods: ' (LOD0, LOD1, LOD2 and the impostor)',
};

/** Downloads an export's one file: the GLB, or the ZIP of the OBJ, its MTL and its textures. */
export function saveExported(
  response: ExportResponse,
  format: ExportFormat,
  report: (s: Status) => void,
) {
  const [file] = response.files;
  if (!file) throw new Error('the exporter returned no file');
  const blob = 'blob' in file ? file.blob : new Blob([file.bytes as BlobPart], { type: file.mime });
  downloadBlob(blob, file.name);
  report({ kind: 'ok', text: `Saved ${file.name}${CONTENTS[format] ?? ''}.` });
}

/** What an export is made from: the tree's inputs, the file stem, and the LOD view. */
export interface ExportSource {
  params: Params;
  volumes: VolumePrimitive[];
  edits: readonly Edit[];
  name: string;
  /** The LOD view's controller (the LOD zip's impostor), null while there is none. */
  lod: LodController | null;
  /** `asset.generator` of the impostor GLB. */
  generator: string;
}

/** Runs one export of the menu (the LOD zip with the impostor of the tree on screen). */
export async function runMeshExport(
  client: Exporter,
  { format, leaves, strict }: MeshExport,
  source: ExportSource,
): Promise<ExportResponse> {
  let impostor = null;
  if (format === 'lods') {
    if (!source.lod) throw new Error('the LOD view is not ready');
    impostor = await impostorFile(source.lod, source.name, source.generator);
  }
  const response = await client.export(source.params, source.volumes, format, {
    name: source.name,
    edits: source.edits,
    ...(leaves ? { leaves } : {}),
    ...(strict ? { strict } : {}),
    ...(impostor ? { impostor: impostor.bytes } : {}),
  });
  if (impostor && impostor.hash !== response.hash) {
    throw new Error('the tree changed while its levels were exported: export again');
  }
  return response;
}
