/** The leaf's texture in three.js, one definition for the viewer, the LOD levels and the forest. */
import {
  DataTexture,
  LinearFilter,
  LinearMipmapLinearFilter,
  RGBAFormat,
  SRGBColorSpace,
  UnsignedByteType,
} from 'three';
import type { LeafTextureBuffers } from '../core/types';

/** RGBA bytes (row 0 = v 0) as an sRGB, mipmapped three.js texture, wrapped without a copy. */
export function srgbTexture(
  rgba: Uint8Array | Uint8ClampedArray,
  width: number,
  height: number,
): DataTexture {
  const t = new DataTexture(rgba, width, height, RGBAFormat, UnsignedByteType);
  t.colorSpace = SRGBColorSpace;
  t.magFilter = LinearFilter;
  t.minFilter = LinearMipmapLinearFilter;
  t.generateMipmaps = true;
  t.needsUpdate = true;
  return t;
}

/** The core's leaf texture as a three.js texture (sRGB, mipmapped). */
export function leafTexture(buffers: LeafTextureBuffers): DataTexture {
  return srgbTexture(buffers.rgba, buffers.width, buffers.height);
}
