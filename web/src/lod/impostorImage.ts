/**
 * The impostor's colour atlas as an image file wants it: the bake (`impostor.ts`) leaves linear
 * albedo premultiplied by coverage in a render target read bottom row first; a PNG base colour
 * texture is sRGB, straight alpha, top row first. Texels the tree does not cover take their
 * frame's mean colour (alpha 0), so filtering and mipmaps toward a leaf's edge blend with the
 * tree's colour instead of black.
 */

/** Linear [0, 1] → sRGB byte (IEC 61966-2-1 transfer function). */
function srgbByte(linear: number): number {
  const c = Math.min(Math.max(linear, 0), 1);
  const s = c <= 0.0031308 ? c * 12.92 : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
  return Math.round(s * 255);
}

/** Linear byte → sRGB byte, for every linear byte value. */
const SRGB = Uint8Array.from({ length: 256 }, (_, i) => srgbByte(i / 255));

/**
 * `pixels`: `size × size` RGBA8 read from the atlas (bottom row first, linear colour
 * premultiplied by alpha) with `frames × frames` frames. Returns the image top row first, sRGB,
 * straight alpha, uncovered texels filled with their frame's mean colour.
 */
export function atlasImage(pixels: Uint8Array, size: number, frames: number): Uint8Array {
  if (pixels.length !== size * size * 4) throw new Error('atlasImage: wrong pixel count');
  const cell = size / frames;
  const out = new Uint8Array(pixels.length);
  for (let fy = 0; fy < frames; fy++) {
    for (let fx = 0; fx < frames; fx++) {
      // The frame's mean linear colour, weighted by coverage (sums of premultiplied colour).
      const sum = [0, 0, 0, 0];
      for (let y = fy * cell; y < (fy + 1) * cell; y++) {
        for (let x = fx * cell; x < (fx + 1) * cell; x++) {
          const o = (y * size + x) * 4;
          for (let k = 0; k < 4; k++) sum[k]! += pixels[o + k]!;
        }
      }
      const mean = [0, 1, 2].map((k) =>
        sum[3]! > 0 ? SRGB[Math.min(255, Math.round((sum[k]! * 255) / sum[3]!))]! : 0,
      );
      for (let y = fy * cell; y < (fy + 1) * cell; y++) {
        const row = size - 1 - y;
        for (let x = fx * cell; x < (fx + 1) * cell; x++) {
          const o = (y * size + x) * 4;
          const t = (row * size + x) * 4;
          const a = pixels[o + 3]!;
          for (let k = 0; k < 3; k++) {
            out[t + k] =
              a === 0 ? mean[k]! : SRGB[Math.min(255, Math.round((pixels[o + k]! * 255) / a))]!;
          }
          out[t + 3] = a;
        }
      }
    }
  }
  return out;
}
