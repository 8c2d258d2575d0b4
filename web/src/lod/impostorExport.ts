/**
 * The impostor file of the LOD export: the LOD view's atlas of the tree on screen (baked with
 * WebGL in the page, `LodController.impostorAtlas`), read back, turned into a PNG
 * (`impostorImage.ts`, `export/png.ts`) and written as a GLB (`impostorGlb.ts`). The export
 * worker stores it in the ZIP next to the three levels.
 */
import type { LodBuffers } from 'sylva-trees/worker';
import { encodePng } from '../export/png';
import type { Vec3 } from './hemiOct';
import { impostorGlb } from './impostorGlb';
import { atlasImage, downsample, powerOfTwoBelow } from './impostorImage';
import type { LodController } from './LodController';
import { treeBox } from './lodObjects';
import { VIEWER_THRESHOLDS } from './selection';

/** Longest the levels of the tree on screen may take to arrive (ms). */
export const IMPOSTOR_WAIT_MS = 90_000;

/** The impostor GLB of the tree on screen and that tree's hash. */
export interface ImpostorFile {
  hash: string;
  bytes: Uint8Array;
}

/** Rejects after `ms` unless `promise` settles first. */
function within<T>(promise: Promise<T>, ms: number, what: string): Promise<T> {
  let timer: ReturnType<typeof setTimeout> | undefined;
  const timeout = new Promise<never>((_, reject) => {
    timer = setTimeout(() => reject(new Error(`${what} took longer than ${ms / 1000} s`)), ms);
  });
  return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

/** The impostor GLB of the tree the LOD view shows, named after `stem`. */
export async function impostorFile(
  controller: LodController,
  stem: string,
  generator: string,
): Promise<ImpostorFile> {
  const { atlas, lods, sphere } = await within(
    controller.impostorAtlas(),
    IMPOSTOR_WAIT_MS,
    'Building the levels of detail',
  );
  const size = atlas.frames * atlas.cellPx;
  // Read at once: the atlas belongs to the LOD view, which drops it with the next tree.
  // Frames must stay whole texels: 8 frames of 160 → 1024 (frames of 128).
  const side = powerOfTwoBelow(size) % atlas.frames === 0 ? powerOfTwoBelow(size) : size;
  const pixels = downsample(atlas.readColor(), size, side);
  const png = encodePng(side, side, atlasImage(pixels, side, atlas.frames));
  const bytes = impostorGlb({
    name: stem,
    png,
    frames: atlas.frames,
    cellPx: side / atlas.frames,
    centre: [sphere.center.x, sphere.center.y, sphere.center.z],
    radius: atlas.radius,
    bounds: box(lods),
    screenSizes: VIEWER_THRESHOLDS,
    generator,
    hash: lods.meta.hash,
  });
  return { hash: lods.meta.hash, bytes };
}

/** The tree's box as two tuples. */
function box(lods: LodBuffers): { min: Vec3; max: Vec3 } {
  const { min, max } = treeBox(lods);
  return { min: [min.x, min.y, min.z], max: [max.x, max.y, max.z] };
}
