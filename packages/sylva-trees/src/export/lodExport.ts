/**
 * Worker side of the levels-of-detail export: the tree's three mesh levels from
 * `generate_lods`, each written by the core as a GLB of its own (`GeneratedLods.to_glb_level`,
 * the same options as a single GLB: leaves, strict), and the impostor GLB the app made from its
 * atlas (the atlas is baked with WebGL on the page, so the request brings that file), stored
 * in one ZIP (docs/formats.md, LOD zip).
 */
import { parseLodMeta } from '../lod/lodHandler';
import type { LodWasmApi, WasmLods } from '../lod/types';
import type { WasmApi } from '../core/types';
import { coreInput } from '../core/editsJson';
import { volumeToCore } from '../core/volumes';
import type { ExportedFile, ExportRequest } from './exportProtocol';
import { zipFiles } from './zip';

/** `GeneratedLods` with the per-level writer (optional: older cores lack it). */
export type ExportableLods = WasmLods & {
  to_glb_level?(level: number, name: string, optionsJson: string): Uint8Array;
};

/** Whether this wasm build can write the levels one by one. */
export function canExportLods(wasm: object): boolean {
  const lods = (wasm as { GeneratedLods?: { prototype?: unknown } }).GeneratedLods;
  const proto = lods?.prototype as Record<string, unknown> | undefined;
  return (
    typeof (wasm as { generate_lods?: unknown }).generate_lods === 'function' &&
    typeof proto?.to_glb_level === 'function'
  );
}

/** The names of the files in the LOD zip of stem `stem`: three levels, then the impostor. */
export function lodFileNames(stem: string): string[] {
  return [0, 1, 2].map((l) => `${stem}_LOD${l}.glb`).concat(`${stem}_impostor.glb`);
}

/**
 * Regenerates the request's tree with its levels and answers the ZIP (`STEM-lods.zip`, or
 * `STEM-lods-strict.zip`) with its content hash. The GLBs are stored, not deflated (their
 * images are PNGs already; the rest shrinks by a few per cent for seconds of work).
 */
export function lodArchive(
  wasm: WasmApi & LodWasmApi,
  request: ExportRequest,
  stem: string,
): { hash: string; file: ExportedFile } {
  if (typeof wasm.generate_lods !== 'function') {
    throw new Error('This Sylva core has no levels-of-detail exporter.');
  }
  const input = coreInput(request.params, request.volumes?.map(volumeToCore), request.edits);
  const lods: ExportableLods = wasm.generate_lods(JSON.stringify(input));
  try {
    if (typeof lods.to_glb_level !== 'function') {
      throw new Error('This Sylva core has no levels-of-detail exporter.');
    }
    const { hash } = parseLodMeta(lods.meta_json());
    const options = JSON.stringify({
      ...(request.leaves ? { leaves: request.leaves } : {}),
      ...(request.strict ? { strict: true } : {}),
    });
    const names = lodFileNames(stem);
    const files = [0, 1, 2].map((level) => ({
      name: names[level]!,
      bytes: lods.to_glb_level!(level, stem, options),
    }));
    if (request.impostor) files.push({ name: names[3]!, bytes: request.impostor });
    const name = `${stem}-lods${request.strict ? '-strict' : ''}.zip`;
    return { hash, file: { name, mime: 'application/zip', bytes: zipFiles(files) } };
  } finally {
    try {
      lods.free();
    } catch {
      // freeing after a trap may fail; the instance is discarded anyway
    }
  }
}
