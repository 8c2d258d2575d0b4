/**
 * Worker side of the mesh export: feature detection of the core's exporters and one export
 * (regenerate, serialise, zip an OBJ's files, transfer). The core's API (`GeneratedTree`): `to_glb_file(options_json)`
 * (the GLB left in the module's memory, read through a view) or `to_glb(options_json)` (a copy),
 * `to_obj(name, options_json)`, `to_mtl(name, options_json)`, `obj_texture_names(name,
 * options_json)` and `obj_texture(options_json, index)` (PNG files the MTL refers to).
 */
import { parseMeta } from '../core/parse';
import type { WasmApi, WasmTree } from '../core/types';
import { coreInput } from '../core/editsJson';
import { volumeToCore } from '../core/volumes';
import type { WorkerResponse } from '../worker/protocol';
import type { ExportedFile, ExportFormat, ExportRequest } from './exportProtocol';
import { zipFiles } from './zip';
import { canExportLods, lodArchive } from './lodExport';

/** A GLB in the core's memory (`GeneratedTree.to_glb_file`): read it, then free it. */
export interface CoreFile {
  ptr(): number;
  byte_length(): number;
  memory(): WebAssembly.Memory;
  free(): void;
}

/** A generated tree with the (optional: older cores and fakes lack them) exporters. */
export type ExportableTree = WasmTree & {
  to_glb_file?(optionsJson: string): CoreFile;
  to_growth_glb_file?(optionsJson: string, age: number, maturity: number): CoreFile;
  to_glb?(optionsJson: string): Uint8Array;
  to_obj?(name: string, optionsJson: string): string;
  to_mtl?(name: string, optionsJson: string): string;
  obj_texture_names?(name: string, optionsJson: string): string[];
  obj_texture?(optionsJson: string, index: number): Uint8Array;
};

/** The formats this wasm build can export, from its `GeneratedTree` class. */
export function exportFormatsOf(wasm: object): ExportFormat[] {
  const tree = (wasm as { GeneratedTree?: { prototype?: unknown } }).GeneratedTree;
  const proto = tree?.prototype;
  if (typeof proto !== 'object' || proto === null) return [];
  const has = (name: string): boolean =>
    typeof (proto as Record<string, unknown>)[name] === 'function';
  const formats: ExportFormat[] = [];
  if (has('to_glb_file') || has('to_glb')) formats.push('glb');
  if (has('to_obj') && has('to_mtl')) formats.push('obj');
  if (has('to_growth_glb_file')) formats.push('glb-growth');
  if (typeof (wasm as YearsApi).growth_years_zip === 'function') formats.push('glb-years');
  if (canExportLods(wasm)) formats.push('lods');
  return formats;
}

/** The core's zip of one GLB per year (optional: older cores and fakes lack it). */
interface YearsApi {
  growth_years_zip?(paramsJson: string, optionsJson: string): Uint8Array;
}

/**
 * `view` as a Blob part: itself, or a copy when it lies in a shared memory (the threaded core's),
 * which a Blob refuses ("The provided ArrayBufferView value must not be shared").
 */
export function blobPart(view: Uint8Array): Uint8Array<ArrayBuffer> {
  return view.buffer instanceof ArrayBuffer ? (view as Uint8Array<ArrayBuffer>) : view.slice();
}

/**
 * A GLB left in the core's memory, read into a Blob at once (before the module could grow its
 * memory), then freed.
 */
function coreBlob(glb: CoreFile, mime: string): Blob {
  try {
    const view = new Uint8Array(glb.memory().buffer, glb.ptr(), glb.byte_length());
    return new Blob([blobPart(view)], { type: mime });
  } finally {
    glb.free();
  }
}

/**
 * The growth exports: the GLB with the growth animation of `tree` (generated from `params`), or
 * the zip of one GLB per year, which the core generates year by year from `input` (the core's
 * generate JSON). Leaves baked in both (the animation cannot morph instances; the years zip is
 * for editors too). Throws when the core lacks the exporter.
 */
export function growthFiles(
  wasm: object,
  tree: ExportableTree,
  format: 'glb-growth' | 'glb-years',
  input: object,
  params: { age?: number; maturity?: number },
  name?: string,
): ExportedFile[] {
  const options = JSON.stringify({ leaves: 'baked' });
  if (format === 'glb-years') {
    const api = wasm as YearsApi;
    if (typeof api.growth_years_zip !== 'function') {
      throw new Error('This Sylva core has no growth exporter.');
    }
    const bytes = api.growth_years_zip(JSON.stringify(input), options);
    return [{ name: `${fileStem(name)}-years.zip`, mime: 'application/zip', bytes }];
  }
  if (typeof tree.to_growth_glb_file !== 'function') {
    throw new Error('This Sylva core has no growth exporter.');
  }
  const mime = 'model/gltf-binary';
  // Absent values are the registry's defaults, as the core took them (Age 40, Mature Age 40).
  const { age = 40, maturity = 40 } = params;
  const blob = coreBlob(tree.to_growth_glb_file(options, age, maturity), mime);
  return [{ name: `${fileStem(name)}-growth.glb`, mime, blob }];
}

/** A safe file stem (letters, digits, `_`, `-`; at most 64), `tree` when nothing is left. */
export function fileStem(name: string | undefined): string {
  const stem = (name ?? '')
    .replace(/[^\w-]+/g, '-')
    .replace(/^-+|-+$/g, '')
    .slice(0, 64);
  return stem === '' ? 'tree' : stem;
}

/** A file name the core made for a texture, reduced to a plain name (never a path). */
function plainName(name: string, fallback: string): string {
  const base = name.split(/[\\/]/).pop() ?? '';
  return /^[\w.-]{1,96}$/.test(base) && !base.startsWith('.') ? base : fallback;
}

/** Serialises a generated tree in `format` (throws when the core lacks that exporter). */
export function exportFiles(
  tree: ExportableTree,
  format: ExportFormat,
  leaves: ExportRequest['leaves'],
  name?: string,
  strict?: boolean,
): ExportedFile[] {
  const options = JSON.stringify({ ...(leaves ? { leaves } : {}), ...(strict ? { strict } : {}) });
  if (format === 'lods') throw new Error('The levels of detail are exported by lodArchive.');
  if (format === 'glb') {
    const stem = `${fileStem(name)}${strict ? '-strict' : ''}`;
    const file = { name: `${stem}.glb`, mime: 'model/gltf-binary' };
    if (typeof tree.to_glb_file === 'function') {
      return [{ ...file, blob: coreBlob(tree.to_glb_file(options), file.mime) }];
    }
    if (typeof tree.to_glb !== 'function') throw new Error('This Sylva core has no GLB exporter.');
    return [{ ...file, bytes: tree.to_glb(options) }];
  }
  if (typeof tree.to_obj !== 'function' || typeof tree.to_mtl !== 'function') {
    throw new Error('This Sylva core has no OBJ exporter.');
  }
  const stem = fileStem(name);
  const encoder = new TextEncoder();
  const files: ExportedFile[] = [
    { name: `${stem}.obj`, mime: 'model/obj', bytes: encoder.encode(tree.to_obj(stem, options)) },
    { name: `${stem}.mtl`, mime: 'model/mtl', bytes: encoder.encode(tree.to_mtl(stem, options)) },
  ];
  const names = tree.obj_texture_names?.(stem, options) ?? [];
  names.forEach((texture, index) => {
    const bytes = tree.obj_texture?.(options, index) ?? new Uint8Array(0);
    if (bytes.length > 0) {
      files.push({ name: plainName(texture, `${stem}_${index}.png`), mime: 'image/png', bytes });
    }
  });
  return files;
}

/**
 * The files of an OBJ export as one download: a ZIP (deflated, `zipFiles`) named after the stem,
 * made here in the worker so the compression never holds up the page.
 */
export function objArchive(files: readonly ExportedFile[], name?: string): ExportedFile {
  const loose = files.flatMap((f) => ('bytes' in f ? [f] : []));
  return { name: `${fileStem(name)}-obj.zip`, mime: 'application/zip', bytes: zipFiles(loose) };
}

/**
 * Answers an export request: regenerates the tree and posts the files (byte buffers
 * transferred, Blobs shared): a GLB, or the OBJ, its MTL and its textures in one ZIP, or the
 * levels of detail in one ZIP (`lodExport.ts`).
 * Throws what `generate` or an exporter threw; the handler reports it like a generate error.
 */
export function exportTree(
  wasm: WasmApi,
  request: ExportRequest,
  post: (message: WorkerResponse, transfer: Transferable[]) => void,
): void {
  if (request.format === 'lods') {
    const { hash, file } = lodArchive(wasm, request, fileStem(request.name));
    const transfer = 'bytes' in file ? [file.bytes.buffer] : [];
    post({ type: 'exported', id: request.id, format: 'lods', hash, files: [file] }, transfer);
    return;
  }
  const input = coreInput(request.params, request.volumes?.map(volumeToCore), request.edits);
  const tree: ExportableTree = wasm.generate(JSON.stringify(input));
  try {
    const { hash } = parseMeta(tree.meta_json());
    const format = request.format;
    const exported =
      format === 'glb-growth' || format === 'glb-years'
        ? growthFiles(wasm, tree, format, input, request.params, request.name)
        : exportFiles(tree, format, request.leaves, request.name, request.strict);
    const files = request.format === 'obj' ? [objArchive(exported, request.name)] : exported;
    post(
      { type: 'exported', id: request.id, format: request.format, hash, files },
      files.flatMap((f) => ('bytes' in f ? [f.bytes.buffer] : [])),
    );
  } finally {
    try {
      tree.free();
    } catch {
      // freeing after a trap may fail; the instance is discarded anyway
    }
  }
}
