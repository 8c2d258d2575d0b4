/**
 * The impostor's colour atlas as an image file wants it: the bake (`impostor.ts`) leaves linear
 * albedo premultiplied by coverage in a render target read bottom row first; a PNG base colour
 * texture is sRGB, straight alpha, top row first. Texels the tree does not cover take their
 * frame's mean colour (alpha 0), so filtering and mipmaps toward a leaf's edge blend with the
 * tree's colour instead of black. An atlas whose side is not a power of two (the app bakes
 * 8 × 160 = 1280 pixels) is first reduced to the power of two below (1024, frames of 128
 * pixels) with an area filter on the premultiplied texels: engines mipmap such textures (Unreal
 * gives a texture of another size no mipmaps) and the Khronos validator flags the other sizes.
 */

/** Linear [0, 1] → sRGB byte (IEC 61966-2-1 transfer function). */
function srgbByte(linear: number): number {
  const c = Math.min(Math.max(linear, 0), 1);
  const s = c <= 0.0031308 ? c * 12.92 : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
  return Math.round(s * 255);
}

/** Linear byte → sRGB byte, for every linear byte value. */
const SRGB = Uint8Array.from({ length: 256 }, (_, i) => srgbByte(i / 255));

/** The largest power of two not above `n`. */
export function powerOfTwoBelow(n: number): number {
  return 2 ** Math.floor(Math.log2(Math.max(n, 1)));
}

/**
 * `size × size` RGBA8 (premultiplied) reduced to `out × out` (`out ≤ size`): each output texel
 * the area-weighted mean of the input texels it covers (separable: rows, then columns).
 */
export function downsample(pixels: Uint8Array, size: number, out: number): Uint8Array {
  if (out === size) return pixels;
  const scale = size / out;
  // For each output column / row: the input texels it covers and their weights.
  const taps = Array.from({ length: out }, (_, o) => {
    const [from, to] = [o * scale, (o + 1) * scale];
    const list: [number, number][] = [];
    for (let i = Math.floor(from); i < Math.min(Math.ceil(to), size); i++) {
      list.push([i, (Math.min(to, i + 1) - Math.max(from, i)) / scale]);
    }
    return list;
  });
  const wide = new Float32Array(size * out * 4);
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < out; x++) {
      for (const [i, w] of taps[x]!) {
        for (let k = 0; k < 4; k++)
          wide[(y * out + x) * 4 + k]! += pixels[(y * size + i) * 4 + k]! * w;
      }
    }
  }
  const result = new Uint8Array(out * out * 4);
  for (let y = 0; y < out; y++) {
    for (let x = 0; x < out; x++) {
      const sum = [0, 0, 0, 0];
      for (const [i, w] of taps[y]!) {
        for (let k = 0; k < 4; k++) sum[k]! += wide[(i * out + x) * 4 + k]! * w;
      }
      for (let k = 0; k < 4; k++) result[(y * out + x) * 4 + k] = Math.round(sum[k]!);
    }
  }
  return result;
}

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
