/**
 * The billboard cloud's leaf-clump atlas, rasterised in plain TypeScript (no canvas, so it runs in
 * a generation worker next to the levels it dresses): a 2×2 atlas whose cells hold
 * `clumpLeaves(cell)` copies of the leaf texture (or green ellipses for a tree without one),
 * scattered over a disc, denser toward the centre, turned at random and seeded, drawn with
 * source-over blending. Each copy samples a mipmap of the leaf (box-filtered halvings, the level
 * whose texels are about a pixel) bilinearly, as a GPU samples a minified texture.
 *
 * A 2D canvas did this on the main thread before; in software-rendered Chromium each atlas took
 * about 2 s there (its draws were flushed through the GPU process), here 10-30 ms.
 */
import { mulberry32 } from '../core/random';
import type { LeafTextureBuffers } from '../core/types';

/**
 * Leaf densities of the clump atlas's cells: the share of the disc its leaves cover (sparse crowns
 * let the sky through a cloud as they do through the leaves).
 */
export const CELL_DENSITY = [0.1, 0.25, 0.5, 1] as const;

/** Leaves in the densest clump cell. */
const MAX_CLUMP_LEAVES = 360;

/** Edge length of the atlas (texels). */
export const CLUMP_SIZE = 512;

/** Cell of the clump atlas (0..3) for a cloud quad's leaf density: the nearest `CELL_DENSITY`. */
export function densityCell(density: number): number {
  let best = 0;
  for (let k = 1; k < CELL_DENSITY.length; k++) {
    if (
      Math.abs(Math.log(density / CELL_DENSITY[k]!)) <
      Math.abs(Math.log(density / CELL_DENSITY[best]!))
    )
      best = k;
  }
  return best;
}

/**
 * Leaves drawn in a clump cell so that they cover about its density of the disc: random leaves
 * cover `1 − exp(−n a / A)`, so `n ∝ −ln(1 − 0.9 d)`, `MAX_CLUMP_LEAVES` at density 1.
 */
export function clumpLeaves(cell: number): number {
  const d = CELL_DENSITY[cell] ?? 1;
  return Math.max(2, Math.round((MAX_CLUMP_LEAVES * Math.log(1 - 0.9 * d)) / Math.log(0.1)));
}

/** One mip level: premultiplied RGBA floats (0..1), rows top-down. */
interface Level {
  width: number;
  height: number;
  texels: Float32Array;
}

/** The leaf's mip chain, level 0 the leaf itself, premultiplied. */
function mipChain(leaf: LeafTextureBuffers): Level[] {
  const { width, height, rgba } = leaf;
  const base = new Float32Array(width * height * 4);
  for (let i = 0; i < width * height; i++) {
    const a = rgba[i * 4 + 3]! / 255;
    base[i * 4] = (rgba[i * 4]! / 255) * a;
    base[i * 4 + 1] = (rgba[i * 4 + 1]! / 255) * a;
    base[i * 4 + 2] = (rgba[i * 4 + 2]! / 255) * a;
    base[i * 4 + 3] = a;
  }
  const levels: Level[] = [{ width, height, texels: base }];
  for (;;) {
    const up = levels[levels.length - 1]!;
    if (up.width === 1 && up.height === 1) return levels;
    const w = Math.max(1, up.width >> 1);
    const h = Math.max(1, up.height >> 1);
    const texels = new Float32Array(w * h * 4);
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w; x++) {
        for (let c = 0; c < 4; c++) {
          let sum = 0;
          for (let dy = 0; dy < 2; dy++) {
            for (let dx = 0; dx < 2; dx++) {
              const sx = Math.min(up.width - 1, x * 2 + dx);
              const sy = Math.min(up.height - 1, y * 2 + dy);
              sum += up.texels[(sy * up.width + sx) * 4 + c]!;
            }
          }
          texels[(y * w + x) * 4 + c] = sum / 4;
        }
      }
    }
    levels.push({ width: w, height: h, texels });
  }
}

/** Bilinear sample of `level` at texel coordinates (`x`, `y`), clamped, into `out`. */
function sample(level: Level, x: number, y: number, out: Float32Array): void {
  const { width, height, texels } = level;
  const fx = Math.min(Math.max(x - 0.5, 0), width - 1);
  const fy = Math.min(Math.max(y - 0.5, 0), height - 1);
  const x0 = Math.floor(fx);
  const y0 = Math.floor(fy);
  const x1 = Math.min(x0 + 1, width - 1);
  const y1 = Math.min(y0 + 1, height - 1);
  const tx = fx - x0;
  const ty = fy - y0;
  for (let c = 0; c < 4; c++) {
    const a = texels[(y0 * width + x0) * 4 + c]!;
    const b = texels[(y0 * width + x1) * 4 + c]!;
    const d = texels[(y1 * width + x0) * 4 + c]!;
    const e = texels[(y1 * width + x1) * 4 + c]!;
    out[c] = (a + (b - a) * tx) * (1 - ty) + (d + (e - d) * tx) * ty;
  }
}

/** Where one leaf goes: centre, turn and height (px), and its flat colour without a texture. */
interface Placed {
  x: number;
  y: number;
  angle: number;
  height: number;
  rgb: [number, number, number];
}

/** Draws rectangle-shaped `leaf` (or an ellipse when `mips` is null) into premultiplied `dst`. */
function drawLeaf(dst: Float32Array, size: number, mips: Level[] | null, leaf: Placed): void {
  const aspect = mips ? mips[0]!.width / mips[0]!.height : 0.44;
  const h = leaf.height;
  const w = h * aspect;
  const cos = Math.cos(leaf.angle);
  const sin = Math.sin(leaf.angle);
  const reach = Math.hypot(w, h) / 2;
  const x0 = Math.max(0, Math.floor(leaf.x - reach));
  const x1 = Math.min(size - 1, Math.ceil(leaf.x + reach));
  const y0 = Math.max(0, Math.floor(leaf.y - reach));
  const y1 = Math.min(size - 1, Math.ceil(leaf.y + reach));
  // The mip whose texels are about one pixel of the drawn leaf.
  const level = mips
    ? mips[Math.min(mips.length - 1, Math.max(0, Math.floor(Math.log2(mips[0]!.height / h))))]!
    : null;
  const src = new Float32Array(4);
  for (let py = y0; py <= y1; py++) {
    for (let px = x0; px <= x1; px++) {
      // The pixel centre in the leaf's own frame (turned back by its angle).
      const dx = px + 0.5 - leaf.x;
      const dy = py + 0.5 - leaf.y;
      const lx = cos * dx + sin * dy;
      const ly = -sin * dx + cos * dy;
      const u = lx / w + 0.5;
      const v = ly / h + 0.5;
      if (level) {
        if (u < 0 || u >= 1 || v < 0 || v >= 1) continue;
        sample(level, u * level.width, v * level.height, src);
      } else {
        const ex = lx / (0.22 * h);
        const ey = ly / (0.5 * h);
        if (ex * ex + ey * ey > 1) continue;
        src[0] = leaf.rgb[0];
        src[1] = leaf.rgb[1];
        src[2] = leaf.rgb[2];
        src[3] = 1;
      }
      const k = (py * size + px) * 4;
      const keep = 1 - src[3]!;
      for (let c = 0; c < 4; c++) dst[k + c] = src[c]! + dst[k + c]! * keep;
    }
  }
}

/**
 * The clump atlas of `leaf` (see the module docs): `size`² RGBA bytes, rows bottom-up as a
 * texture's, the (almost) transparent texels carrying the mean colour of the opaque ones (so
 * mipmaps average leaf colour with leaf colour, not with black). Same `leaf` and `seed`, same
 * bytes.
 */
export function clumpAtlas(
  leaf: LeafTextureBuffers | null,
  seed = 7,
  size = CLUMP_SIZE,
): Uint8Array {
  const mips = leaf && leaf.width > 0 && leaf.height > 0 ? mipChain(leaf) : null;
  const dst = new Float32Array(size * size * 4);
  const half = size / 2;
  for (let cell = 0; cell < 4; cell++) {
    const rand = mulberry32(seed + cell);
    const ox = (cell % 2) * half;
    // Image rows run top-down here, texture v bottom-up: cell row 0 is the bottom half.
    const oy = (1 - Math.floor(cell / 2)) * half;
    const count = clumpLeaves(cell);
    for (let i = 0; i < count; i++) {
      const r = Math.sqrt(rand()) * half * 0.4;
      const a = rand() * Math.PI * 2;
      const placed: Placed = {
        x: ox + half / 2 + Math.cos(a) * r,
        y: oy + half / 2 + Math.sin(a) * r,
        height: half * (0.06 + 0.03 * rand()),
        angle: rand() * Math.PI * 2,
        rgb: [0, 0, 0],
      };
      if (!mips) {
        const g = (110 + Math.floor(rand() * 60)) / 255;
        placed.rgb = [g * 0.45, g, g * 0.3];
      }
      drawLeaf(dst, size, mips, placed);
    }
  }
  return toTexture(dst, size);
}

/** Premultiplied float RGBA (rows top-down) as straight RGBA bytes, rows bottom-up, bled. */
function toTexture(dst: Float32Array, size: number): Uint8Array {
  const out = new Uint8Array(size * size * 4);
  let [r, g, b, n] = [0, 0, 0, 0];
  for (let y = 0; y < size; y++) {
    const from = (size - 1 - y) * size * 4;
    for (let x = 0; x < size; x++) {
      const s = from + x * 4;
      const d = (y * size + x) * 4;
      const a = dst[s + 3]!;
      const un = a > 0 ? 1 / a : 0;
      for (let c = 0; c < 3; c++) out[d + c] = Math.round(Math.min(1, dst[s + c]! * un) * 255);
      out[d + 3] = Math.round(Math.min(1, a) * 255);
      if (out[d + 3]! >= 128) {
        r += out[d]!;
        g += out[d + 1]!;
        b += out[d + 2]!;
        n++;
      }
    }
  }
  const mean = [r, g, b].map((v) => (n > 0 ? Math.round(v / n) : 0));
  for (let i = 0; i < out.length; i += 4) {
    if (out[i + 3]! < 8) {
      out[i] = mean[0]!;
      out[i + 1] = mean[1]!;
      out[i + 2] = mean[2]!;
    }
  }
  return out;
}
