/**
 * The bark's look in the viewer, after the core's bark types (`sylva_core::mesh::bark`;
 * docs/look.md, Bark types): the texture's tiling follows each stem's girth the way real bark does (`BarkStyle`:
 * tiles around = girth / (tile_at_1m · √girth), blended between the two nearest powers of two so
 * the seam at u = 1 still meets u = 0), thin stems fade to smooth young bark of the type's
 * colour, and the core's per-vertex occlusion (`TreeMesh.shade`: crown depth, tree holes)
 * darkens the colour and hides the reflections. The stem radius comes from the wind data (`radius`, read from the same GPU
 * buffer); GLSL lives in `shaders/bark*.glsl`.
 */
import {
  BufferAttribute,
  Color,
  InterleavedBufferAttribute,
  ShaderChunk,
  type BufferGeometry,
  type Material,
  type WebGLProgramParametersWithUniforms,
} from 'three';
import type { BarkStyle } from '../core/types';
import bodyVert from './shaders/barkBody.vert.glsl?raw';
import mapFrag from './shaders/barkMap.frag.glsl?raw';
import parsFrag from './shaders/barkPars.frag.glsl?raw';
import parsVert from './shaders/barkPars.vert.glsl?raw';
import roughnessFrag from './shaders/barkRoughness.frag.glsl?raw';

/** Stem radius (m) assumed where a tree has no wind data. */
export const FALLBACK_RADIUS = 0.3;
const MARKER = '// sylva-bark-look';
/**
 * The occlusion darkens the colour (barkMap.frag.glsl), which scales the diffuse light; the
 * reflections of the sky and the sun are hidden as much (the inside of a tree hole reflected
 * the bright sky off its walls and read as lit bark).
 */
const SHADE_SPECULAR = `reflectedLight.indirectSpecular *= vBark.z;
reflectedLight.directSpecular *= vBark.z;`;

/** The bark look's uniforms, shared by every program of one material. */
export interface BarkLookUniforms {
  uBarkTile: { value: number };
  uBarkYoungRadius: { value: number };
  uBarkYoung: { value: Color };
}

/** Uniforms with a neutral style until the core's style arrives. */
export function createBarkLookUniforms(): BarkLookUniforms {
  return {
    uBarkTile: { value: 0.25 },
    uBarkYoungRadius: { value: 0.02 },
    uBarkYoung: { value: new Color(0.3, 0.25, 0.18) },
  };
}

/** Copies a bark type's style into the uniforms (`young_rgb` is linear already). */
export function setBarkStyle(uniforms: BarkLookUniforms, style: BarkStyle): void {
  uniforms.uBarkTile.value = style.tile_at_1m;
  uniforms.uBarkYoungRadius.value = style.young_radius;
  uniforms.uBarkYoung.value.setRGB(...style.young_rgb);
}

function replaceOnce(source: string, chunk: string, by: string): string {
  if (!source.includes(chunk)) throw new Error(`bark look: the shader has no ${chunk}`);
  return source.replace(chunk, by);
}

/** Injects the bark look into a MeshStandardMaterial's shaders. */
export function patchBarkShader(
  shader: Pick<WebGLProgramParametersWithUniforms, 'vertexShader' | 'fragmentShader' | 'uniforms'>,
  uniforms: BarkLookUniforms,
): void {
  if (shader.vertexShader.includes(MARKER)) return;
  // Every fetch: the chunk has one for object-space and one for tangent-space normal maps.
  const normalMaps = ShaderChunk.normal_fragment_maps
    .replaceAll('texture2D( normalMap, vNormalMapUv )', 'barkSample( normalMap, vNormalMapUv )')
    .replace('mapN.xy *= normalScale;', 'mapN.xy *= normalScale * ( 1.0 - vBark.y );');
  const ao = `${ShaderChunk.aomap_fragment.replaceAll(
    'texture2D( aoMap, vAoMapUv )',
    'barkSample( aoMap, vAoMapUv )',
  )}\n${SHADE_SPECULAR}`;
  let v = replaceOnce(
    shader.vertexShader,
    '#include <common>',
    `#include <common>\n${MARKER}\n${parsVert}`,
  );
  v = replaceOnce(v, '#include <begin_vertex>', `#include <begin_vertex>\n${bodyVert}`);
  let f = replaceOnce(shader.fragmentShader, '#include <common>', `#include <common>\n${parsFrag}`);
  f = replaceOnce(f, '#include <map_fragment>', mapFrag);
  f = replaceOnce(f, '#include <roughnessmap_fragment>', roughnessFrag);
  f = replaceOnce(f, '#include <normal_fragment_maps>', normalMaps);
  f = replaceOnce(f, '#include <aomap_fragment>', ao);
  shader.vertexShader = v;
  shader.fragmentShader = f;
  Object.assign(shader.uniforms, uniforms);
}

/** Gives `material` the bark look (after any earlier `onBeforeCompile`, e.g. the wind's). */
export function applyBarkLook(material: Material, uniforms: BarkLookUniforms): void {
  const previous = material.onBeforeCompile.bind(material);
  const previousKey = material.customProgramCacheKey.bind(material);
  material.onBeforeCompile = (shader, renderer) => {
    previous(shader, renderer);
    patchBarkShader(shader, uniforms);
  };
  material.customProgramCacheKey = () => `${previousKey()}-sylva-bark`;
  material.needsUpdate = true;
}

/**
 * The bark look's attributes: `barkRadius` (a view of the wind buffer's radius, no copy; a
 * constant where there is no wind data) and `barkShade` (the core's occlusion bytes, normalised;
 * open sky where it sent none).
 */
export function attachBarkAttributes(
  geometry: BufferGeometry,
  shade: Uint8Array | undefined,
): void {
  const count = geometry.getAttribute('position').count;
  const wind = geometry.getAttribute('windParams');
  geometry.setAttribute(
    'barkRadius',
    wind instanceof InterleavedBufferAttribute
      ? new InterleavedBufferAttribute(wind.data, 1, 7)
      : new BufferAttribute(new Float32Array(count).fill(FALLBACK_RADIUS), 1),
  );
  geometry.setAttribute('barkShade', new BufferAttribute(shadeBytes(shade, count), 1, true));
}

/** `shade` when it has one byte per vertex, else open sky (255) for every vertex. */
export function shadeBytes(shade: Uint8Array | undefined, count: number): Uint8Array {
  return shade && shade.length === count ? shade : new Uint8Array(count).fill(255);
}
