/**
 * Alpha-tested leaves that keep their coverage at a distance. A leaf texture's smaller mip levels
 * average the opaque blade with the transparent texels around it; for a lobed or narrow leaf
 * that average falls under the alpha cutoff, and a far crown thins out to its twigs (the
 * gallery's CA Black Oak, 363,000 deeply lobed leaves, showed bare brown branches). The sampled
 * alpha is scaled up by the mip level the fragment reads, `alpha · (1 + mip · s)` (Ben Golus,
 * "Anti-aliased Alpha Test: The Esoteric Alpha To Coverage", 2017; `s` = 0.25), so a leaf
 * covers about as much of the screen as its full-size texture says. Up close (mip 0) nothing
 * changes.
 */
import type { Material } from 'three';
import { chainFragmentPatch } from './fragmentPatch';
import leafCoverage from './shaders/leafCoverage.frag.glsl?raw';

/** Alpha gain per mip level (`s` above). */
export const LEAF_MIP_ALPHA_SCALE = 0.25;

/**
 * Adds the mip-scaled alpha to an alpha-tested, texture-mapped material (after any earlier
 * patch: wind, translucency). Materials without a map are unchanged.
 */
export function applyLeafCoverage(material: Material): void {
  chainFragmentPatch(material, {
    key: 'sylva-leaf-coverage',
    at: '#include <map_fragment>',
    where: 'after',
    code: leafCoverage,
    uniforms: { uLeafMipAlphaScale: LEAF_MIP_ALPHA_SCALE },
  });
}
