/**
 * The Season's flowers, fruit, catkins and buds as parts of the impostor bake (`impostor.ts`
 * `BakePart`): each organ set's geometry drawn through its instance matrices and tints, in its
 * own colour (the core's sRGB), so a tree's impostor in September shows its fruit. Petals and
 * samara wings are single blades and are baked two-sided and lit like leaves; the rest are
 * closed solids.
 */
import { Color, SRGBColorSpace } from 'three';
import type { OrganSetBuffers } from 'sylva-trees/core';
import { organGeometry } from 'sylva-trees/viewer';
import type { BakePart } from './impostor';

/** The bake parts of `sets` (the caller disposes their geometries after the bake). */
export function organBakeParts(sets: OrganSetBuffers[]): BakePart[] {
  return sets.map((set) => ({
    geometry: organGeometry(set),
    instances: { matrices: set.matrices, colors: set.colors },
    color: `#${new Color().setRGB(...set.color, SRGBColorSpace).getHexString()}`,
    map: null,
    doubleSided: set.kind === 'petals' || set.kind === 'fruit_part',
  }));
}
