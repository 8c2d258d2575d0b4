/**
 * The material of a cut stem's face (mesh group `cut_face`): a `MeshStandardMaterial` with the
 * core's procedural end grain of the tree's bark type (baked in the worker by `end_grain_maps`)
 * as colour and tangent-space normal map. The face's uvs are disc coordinates (pith at 0.5, 0.5,
 * the rim at radius 0.49 · 0.92), so the disc texture lies on the face with its rings round the
 * stem's axis; the maps clamp at the edge (nothing is drawn outside the disc).
 */
import type { DataTexture } from 'three';
import { ClampToEdgeWrapping, MeshStandardMaterial, Vector2 } from 'three';
import type { EndGrainBuffers } from '../core/types';
import { mipmappedTexture } from './barkMaterial';

/** Pale wood until the end grain arrives (and the multiplier is white after). */
export const CUT_FACE_FLAT_COLOR = '#c8a57a';
/** Sawn end grain is rough (the core's `end_grain::ROUGHNESS`). */
export const CUT_FACE_ROUGHNESS = 0.85;
/** Depth of the rings and checks in the lighting. */
export const CUT_FACE_NORMAL_SCALE = 1;

/** A new cut-face material (a flat wood colour until `EndGrainTextures.set` gives it maps). */
export function createCutFaceMaterial(): MeshStandardMaterial {
  const material = new MeshStandardMaterial({
    color: CUT_FACE_FLAT_COLOR,
    roughness: CUT_FACE_ROUGHNESS,
  });
  material.name = 'cut_face';
  return material;
}

/** A clamped, mipmapped disc texture of RGBA8 texels (row 0 = v 0). */
function discTexture(rgba: Uint8Array, size: number, srgb: boolean): DataTexture {
  return mipmappedTexture(rgba, size, srgb, ClampToEdgeWrapping);
}

/** Owns the end-grain maps of one cut-face material. */
export class EndGrainTextures {
  private color: DataTexture | null = null;
  private normal: DataTexture | null = null;
  /** The bark type the maps are, -1 before any. */
  kind = -1;

  constructor(private readonly material: MeshStandardMaterial) {}

  /** Size of the colour map, or null before the maps arrived. */
  get size(): number | null {
    const image = this.color?.image as { width: number } | undefined;
    return image ? image.width : null;
  }

  /** Replaces the maps with the worker's baked end grain (ignored when the sizes are wrong). */
  set(grain: EndGrainBuffers): void {
    const texels = grain.size * grain.size * 4;
    if (grain.size < 1 || grain.color.length !== texels || grain.normal.length !== texels) return;
    this.dispose();
    this.color = discTexture(grain.color, grain.size, true);
    this.normal = discTexture(grain.normal, grain.size, false);
    this.material.map = this.color;
    this.material.normalMap = this.normal;
    this.material.normalScale = new Vector2(CUT_FACE_NORMAL_SCALE, CUT_FACE_NORMAL_SCALE);
    this.material.color.set('#ffffff');
    this.material.needsUpdate = true;
    this.kind = grain.kind;
  }

  /** Releases the textures (the material keeps its flat colour). */
  dispose(): void {
    this.color?.dispose();
    this.normal?.dispose();
    if (this.color) {
      this.material.map = null;
      this.material.normalMap = null;
      this.material.color.set(CUT_FACE_FLAT_COLOR);
      this.material.needsUpdate = true;
    }
    this.color = null;
    this.normal = null;
    this.kind = -1;
  }
}
