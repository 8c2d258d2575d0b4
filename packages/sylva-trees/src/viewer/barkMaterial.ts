/**
 * The bark material: a `MeshStandardMaterial` with the core's procedural maps of the tree's bark
 * type (baked in the worker by `bark_maps`, no downloaded images) as colour map, tangent-space
 * normal map and occlusion-roughness map, and the type's style for the bark look (barkLook.ts).
 *
 * Bark UVs (see `TreeMesh`): `u` runs around the stem 0..1, `v` along it at one unit per
 * circumference, so an equal repeat in u and v keeps the texels square on every stem. The repeat
 * in u must be an integer (the seam at u = 1 must match u = 0): the texture's own repeat is 1 and
 * the bark look scales it per stem by integer powers of two.
 */
import {
  DataTexture,
  LinearFilter,
  LinearMipmapLinearFilter,
  MeshStandardMaterial,
  NoColorSpace,
  RGBAFormat,
  RepeatWrapping,
  SRGBColorSpace,
  UnsignedByteType,
  Vector2,
  type Wrapping,
} from 'three';
import type { BarkTextureBuffers } from '../core/types';
import { setBarkStyle, type BarkLookUniforms } from './barkLook';

/** The texture's own repeat: the bark look multiplies it by the stem's tiles around. */
export const BARK_REPEAT = 1;
/** Flat colour until the textures arrive (and the multiplier is white after). */
export const BARK_FLAT_COLOR = '#5b3d26';
/** Depth of the fissures in the lighting (times the type's `relief`). */
export const BARK_NORMAL_SCALE = 1;

/** A new bark material (flat colour until `BarkTextures.set` gives it maps). */
export function createBarkMaterial(): MeshStandardMaterial {
  return new MeshStandardMaterial({ color: BARK_FLAT_COLOR, roughness: 0.92 });
}

/**
 * A mipmapped texture of `size`² RGBA8 texels (row 0 = v 0), sRGB colour or linear data,
 * repeating or clamped at its edges (`wrap`), anisotropic.
 */
export function mipmappedTexture(
  rgba: Uint8Array,
  size: number,
  srgb: boolean,
  wrap: Wrapping,
): DataTexture {
  const texture = new DataTexture(rgba, size, size, RGBAFormat, UnsignedByteType);
  texture.colorSpace = srgb ? SRGBColorSpace : NoColorSpace;
  texture.wrapS = wrap;
  texture.wrapT = wrap;
  texture.magFilter = LinearFilter;
  texture.minFilter = LinearMipmapLinearFilter;
  texture.generateMipmaps = true;
  texture.anisotropy = 4;
  texture.flipY = false;
  texture.needsUpdate = true;
  return texture;
}

/** A repeating, mipmapped texture of RGBA8 texels (row 0 = v 0). */
export function bakedTexture(rgba: Uint8Array, size: number, srgb: boolean): DataTexture {
  const texture = mipmappedTexture(rgba, size, srgb, RepeatWrapping);
  texture.repeat.set(BARK_REPEAT, BARK_REPEAT);
  return texture;
}

/** Owns the bark maps of one material. */
export class BarkTextures {
  private color: DataTexture | null = null;
  private normal: DataTexture | null = null;
  private orm: DataTexture | null = null;
  /** The bark type the maps are, -1 before any. */
  kind = -1;

  constructor(
    private readonly material: MeshStandardMaterial,
    /** The bark look's uniforms, given the type's style with its maps. */
    private readonly look?: BarkLookUniforms,
  ) {}

  /** Size of the colour map, or null before the textures arrived. */
  get size(): { width: number; height: number } | null {
    const image = this.color?.image as { width: number; height: number } | undefined;
    return image ? { width: image.width, height: image.height } : null;
  }

  /** Replaces the maps with the worker's baked textures. */
  set(bark: BarkTextureBuffers): void {
    const texels = bark.size * bark.size * 4;
    const sizes = [bark.color, bark.normal, bark.orm].map((m) => m.length);
    if (bark.size < 1 || sizes.some((n) => n !== texels)) return;
    this.dispose();
    this.color = bakedTexture(bark.color, bark.size, true);
    this.normal = bakedTexture(bark.normal, bark.size, false);
    this.orm = bakedTexture(bark.orm, bark.size, false);
    this.material.map = this.color;
    this.material.normalMap = this.normal;
    // Roughness from the ORM map's G; its occlusion (R) stays for the exports: one fetch less
    // per bark fragment on software WebGL.
    this.material.roughnessMap = this.orm;
    this.material.roughness = 1;
    const relief = BARK_NORMAL_SCALE * bark.style.relief;
    this.material.normalScale = new Vector2(relief, relief);
    this.material.color.set('#ffffff');
    this.material.needsUpdate = true;
    if (this.look) setBarkStyle(this.look, bark.style);
    this.kind = bark.kind;
  }

  /** Releases the textures (the material keeps its flat colour). */
  dispose(): void {
    this.color?.dispose();
    this.normal?.dispose();
    this.orm?.dispose();
    if (this.color) {
      this.material.map = null;
      this.material.normalMap = null;
      this.material.roughnessMap = null;
      this.material.roughness = 0.92;
      this.material.color.set(BARK_FLAT_COLOR);
      this.material.needsUpdate = true;
    }
    this.color = null;
    this.normal = null;
    this.orm = null;
    this.kind = -1;
  }
}
