/**
 * Forest instancing data, plain TypeScript (no three.js) so it can be tested and benchmarked:
 *
 * * `scatter`: a seeded jittered grid (every tree in its own cell, jittered by at most
 *   `jitter / 2` of a cell, so no two trees are closer than `(1 − jitter)` cells), a variety, a
 *   rotation about Y and a scale per tree, and each tree's 4×4 instance matrix computed once.
 * * `createBuckets` / `assignLods`: per frame, each tree's level of detail from its distance to
 *   the camera (screen-size thresholds with hysteresis, see `lod/selection.ts`), then its matrix
 *   copied into the preallocated buffer of its (variety, level) bucket. Nothing is allocated per
 *   frame; the renderer uploads `counts[b] × 16` floats of bucket `b` and draws `counts[b]`
 *   instances, so the number of draws depends on varieties × levels only, never on N.
 */
import { mulberry32 } from 'sylva-trees/core';

/** Levels per tree in the forest: LOD0, LOD1, LOD2 and the impostor. */
export const FOREST_LEVELS = 4;

/** Scatter settings. */
export interface ScatterOptions {
  /** Seed of the placement, varieties, rotations and scales. */
  seed: number;
  /** Number of tree varieties to pick from (uniformly). */
  varieties: number;
  /** Grid cell size (m): the mean distance between neighbouring trees. */
  spacing: number;
  /** Jitter as a fraction of a cell (0 = regular grid, < 1 keeps trees apart); default 0.6. */
  jitter?: number;
  /** Scale range `[min, max]`; default [0.8, 1.2]. */
  scale?: [number, number];
}

/** Where the trees stand. */
export interface ForestLayout {
  count: number;
  x: Float32Array;
  z: Float32Array;
  /** Rotation about Y (radians). */
  rotation: Float32Array;
  scale: Float32Array;
  variety: Uint8Array;
  /** Column-major 4×4 instance matrix per tree (rotation, scale, translation). */
  matrices: Float32Array;
  /** Half the side of the square the trees stand in (m), centred on the origin. */
  halfSize: number;
  /** Smallest distance any two trees may have (m). */
  minSpacing: number;
  /** Trees per variety. */
  perVariety: Int32Array;
}

/** Places `n` trees (see the module docs). */
export function scatter(n: number, options: ScatterOptions): ForestLayout {
  const count = Math.max(0, Math.floor(n));
  const varieties = Math.max(1, Math.min(255, Math.floor(options.varieties)));
  const jitter = Math.min(Math.max(options.jitter ?? 0.6, 0), 0.95);
  const [smin, smax] = options.scale ?? [0.8, 1.2];
  const cell = options.spacing;
  const cols = Math.max(1, Math.ceil(Math.sqrt(count)));
  const rows = Math.max(1, Math.ceil(count / cols));
  const x = new Float32Array(count);
  const z = new Float32Array(count);
  const rotation = new Float32Array(count);
  const scale = new Float32Array(count);
  const variety = new Uint8Array(count);
  const matrices = new Float32Array(count * 16);
  const perVariety = new Int32Array(varieties);
  const rand = mulberry32(options.seed);
  const x0 = -((cols - 1) * cell) / 2;
  const z0 = -((rows - 1) * cell) / 2;
  for (let i = 0; i < count; i++) {
    const col = i % cols;
    const row = (i - col) / cols;
    const px = x0 + col * cell + (rand() - 0.5) * jitter * cell;
    const pz = z0 + row * cell + (rand() - 0.5) * jitter * cell;
    const v = Math.min(Math.floor(rand() * varieties), varieties - 1);
    const r = rand() * Math.PI * 2;
    const s = smin + (smax - smin) * rand();
    x[i] = px;
    z[i] = pz;
    rotation[i] = r;
    scale[i] = s;
    variety[i] = v;
    perVariety[v]!++;
    const c = Math.cos(r) * s;
    const sn = Math.sin(r) * s;
    const o = i * 16;
    matrices[o] = c;
    matrices[o + 2] = -sn;
    matrices[o + 5] = s;
    matrices[o + 8] = sn;
    matrices[o + 10] = c;
    matrices[o + 12] = px;
    matrices[o + 14] = pz;
    matrices[o + 15] = 1;
  }
  return {
    count,
    x,
    z,
    rotation,
    scale,
    variety,
    matrices,
    halfSize: (Math.max(cols, rows) * cell) / 2,
    minSpacing: (1 - jitter) * cell,
    perVariety,
  };
}

/** Per-(variety, level) instance buffers, preallocated once per layout. */
export interface LodBuckets {
  varieties: number;
  levels: number;
  /** Bucket `v * levels + l`: room for every tree of variety `v` (16 floats each). */
  matrices: Float32Array[];
  /** Instances written into each bucket by the last `assignLods`. */
  counts: Int32Array;
  /** Current level per tree (the hysteresis state). */
  level: Uint8Array;
  /** Trees per level after the last `assignLods` (culled trees in none). */
  perLevel: Int32Array;
}

/** Allocates the buckets for `layout` (every tree starts at the coarsest level). */
export function createBuckets(
  layout: ForestLayout,
  varieties: number,
  levels = FOREST_LEVELS,
): LodBuckets {
  const matrices: Float32Array[] = [];
  for (let v = 0; v < varieties; v++) {
    const room = layout.perVariety[v] ?? 0;
    for (let l = 0; l < levels; l++) matrices.push(new Float32Array(room * 16));
  }
  return {
    varieties,
    levels,
    matrices,
    counts: new Int32Array(varieties * levels),
    level: new Uint8Array(layout.count).fill(levels - 1),
    perLevel: new Int32Array(levels),
  };
}

/** What `assignLods` needs besides the layout: camera, per-variety sizes, switch distances. */
export interface LodFrame {
  /** Camera position (m). */
  camera: [number, number, number];
  /** Bounding-sphere radius of each variety at scale 1 (m). */
  radius: Float32Array;
  /** Height of each variety's bounding-sphere centre at scale 1 (m). */
  centreY: Float32Array;
  /** `switchDistances(...).out`: per threshold, the distance in radii to go one level coarser. */
  out: readonly number[];
  /** `switchDistances(...).back`: per threshold, the distance in radii to come back finer. */
  back: readonly number[];
  /**
   * Optional view frustum: 6 planes as `nx, ny, nz, d` (inside where `n·p + d ≥ −r`); trees
   * wholly outside are skipped.
   */
  planes?: Float32Array;
}

/**
 * Assigns every tree its level (hysteresis on `buckets.level`) and writes its matrix into its
 * bucket. Allocation-free; returns the number of trees written (visible).
 */
export function assignLods(layout: ForestLayout, buckets: LodBuckets, frame: LodFrame): number {
  const { counts, level, matrices, levels, perLevel } = buckets;
  const { camera, radius, centreY, out, back, planes } = frame;
  const last = levels - 1;
  counts.fill(0);
  perLevel.fill(0);
  const [cx, cy, cz] = camera;
  const src = layout.matrices;
  let visible = 0;
  for (let i = 0; i < layout.count; i++) {
    const v = layout.variety[i]!;
    const s = layout.scale[i]!;
    const r = radius[v]! * s;
    const tx = layout.x[i]!;
    const ty = centreY[v]! * s;
    const tz = layout.z[i]!;
    if (planes) {
      let inside = true;
      for (let p = 0; p < 24; p += 4) {
        if (planes[p]! * tx + planes[p + 1]! * ty + planes[p + 2]! * tz + planes[p + 3]! < -r) {
          inside = false;
          break;
        }
      }
      if (!inside) continue;
    }
    const dx = tx - cx;
    const dy = ty - cy;
    const dz = tz - cz;
    const d2 = dx * dx + dy * dy + dz * dz;
    const r2 = r * r;
    let l = level[i]!;
    while (l < last && d2 > out[l]! * out[l]! * r2) l++;
    while (l > 0 && d2 < back[l - 1]! * back[l - 1]! * r2) l--;
    level[i] = l;
    const b = v * levels + l;
    const dst = matrices[b]!;
    const o = counts[b]! * 16;
    const so = i * 16;
    for (let k = 0; k < 16; k++) dst[o + k] = src[so + k]!;
    counts[b]!++;
    perLevel[l]!++;
    visible++;
  }
  return visible;
}

/** Scatter + buckets + one assignment from a camera at the forest's edge (the benchmarked work). */
export function buildForestInstancing(
  n: number,
  varieties: number,
  seed = 1,
): { layout: ForestLayout; buckets: LodBuckets; visible: number } {
  const layout = scatter(n, { seed, varieties, spacing: 9 });
  const buckets = createBuckets(layout, varieties);
  const radius = new Float32Array(varieties).fill(6);
  const centreY = new Float32Array(varieties).fill(6);
  const t = Math.tan((40 * Math.PI) / 360);
  const thresholds = [0.6, 0.3, 0.12];
  const visible = assignLods(layout, buckets, {
    camera: [0, 20, layout.halfSize + 30],
    radius,
    centreY,
    out: thresholds.map((x) => 1 / (x * 0.9 * t)),
    back: thresholds.map((x) => 1 / (x * 1.1 * t)),
  });
  return { layout, buckets, visible };
}
