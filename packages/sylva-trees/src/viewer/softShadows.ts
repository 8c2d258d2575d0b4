/**
 * Smooth soft shadows without temporal antialiasing. three.js (r187) filters a directional
 * light's shadow with 5 taps of a Vogel disk rotated per pixel by interleaved gradient noise, a
 * pattern made for TAA to average over frames; a viewer that draws a still frame shows it as
 * grain, strongest in the dappled shade under a crown. This patch samples a fixed 16-tap Vogel
 * disk instead (each tap a hardware 2 × 2 comparison, so 64 texels over the same radius): the
 * penumbra is a smooth blur of the shadow map. A fixed disk of few taps shows copies of the
 * leaves' shadows at its offsets (5 taps: blobs, a 3 × 3 grid: cross-hatch); at 16 they merge.
 * In software WebGL a frame of the default tree takes about 15 % longer (0.69 s against 0.60 s
 * in SwiftShader, measured side by side); reading four taps first and skipping the rest where
 * they agree cost as much and left specks at the edges it skipped. Only the directional light's
 * PCF filter changes; point and spot lights keep three's.
 */
import { ShaderChunk, type Material } from 'three';

/** Taps of the fixed disk. */
export const SOFT_SHADOW_TAPS = 16;

/** The disk's offsets (unit radius): Vogel's spiral, `r = √((i + ½) / n)`, golden-angle turns. */
export function vogelDisk(n: number): [number, number][] {
  const golden = Math.PI * (3 - Math.sqrt(5));
  return Array.from({ length: n }, (_, i) => {
    const r = Math.sqrt((i + 0.5) / n);
    return [r * Math.cos(i * golden), r * Math.sin(i * golden)];
  });
}

/** three's rotated 5-tap filter of a directional light (the first PCF `getShadow`). */
const ROTATED_TAPS =
  /float phi = interleavedGradientNoise\( gl_FragCoord\.xy \) \* PI2;[\s\S]*?\) \* 0\.2;/;

function fixedTaps(): string {
  const taps = vogelDisk(SOFT_SHADOW_TAPS)
    .map(([x, y]) => `vec2( ${x.toFixed(6)}, ${y.toFixed(6)} )`)
    .join(',\n\t\t\t\t\t');
  return `// sylva-soft-shadows: a fixed ${SOFT_SHADOW_TAPS}-tap Vogel disk, no per-pixel noise.
				const vec2 sylvaTaps[ ${SOFT_SHADOW_TAPS} ] = vec2[](
					${taps}
				);
				shadow = 0.0;
				for ( int i = 0; i < ${SOFT_SHADOW_TAPS}; i ++ ) {
					shadow += texture( shadowMap, vec3( shadowCoord.xy + sylvaTaps[ i ] * radius, shadowCoord.z ) );
				}
				shadow *= ${(1 / SOFT_SHADOW_TAPS).toFixed(6)};`;
}

let chunk: string | null = null;

/** three's `shadowmap_pars_fragment` with the fixed disk (built once). */
export function softShadowChunk(): string {
  if (chunk !== null) return chunk;
  const source = ShaderChunk.shadowmap_pars_fragment;
  if (!ROTATED_TAPS.test(source)) {
    throw new Error("soft shadows: three's PCF filter is not the one this patch replaces");
  }
  chunk = source.replace(ROTATED_TAPS, fixedTaps());
  return chunk;
}

const INCLUDE = '#include <shadowmap_pars_fragment>';

/** Gives `material` the smooth filter (after any earlier `onBeforeCompile`). */
export function applySoftShadows(material: Material): void {
  const previous = material.onBeforeCompile.bind(material);
  const previousKey = material.customProgramCacheKey.bind(material);
  material.onBeforeCompile = (shader, renderer) => {
    previous(shader, renderer);
    if (shader.fragmentShader.includes(INCLUDE)) {
      shader.fragmentShader = shader.fragmentShader.replace(INCLUDE, softShadowChunk());
    }
  };
  material.customProgramCacheKey = () => `${previousKey()}-sylva-soft-shadows`;
  material.needsUpdate = true;
}
