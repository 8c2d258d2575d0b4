// The impostor bakes the Season's parts: each organ set becomes a part drawn through its own
// instance matrices and tints, in its sRGB colour, petals and wings two-sided.
import { describe, expect, it } from 'vitest';
import type { OrganSetBuffers } from 'sylva-trees/core';
import { organBakeParts } from './organParts';

function set(kind: OrganSetBuffers['kind'], color: [number, number, number]): OrganSetBuffers {
  return {
    kind,
    name: kind,
    color,
    roughness: 0.5,
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
    normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1]),
    indices: new Uint32Array([0, 1, 2]),
    matrices: new Float32Array(32),
    colors: new Float32Array([1, 1, 1, 0.9, 0.9, 0.9]),
  };
}

describe('organBakeParts', () => {
  it('bakes every set through its instances in its own colour', () => {
    const sets = [set('fruit', [0.5, 0.25, 0]), set('petals', [1, 1, 1])];
    const parts = organBakeParts(sets);
    expect(parts).toHaveLength(2);
    expect(parts[0]!.color).toBe('#804000');
    expect(parts[0]!.instances?.matrices).toBe(sets[0]!.matrices);
    expect(parts[0]!.instances?.colors).toBe(sets[0]!.colors);
    expect(parts[0]!.geometry.getAttribute('position').count).toBe(3);
    expect([parts[0]!.doubleSided, parts[1]!.doubleSided]).toEqual([false, true]);
  });
});
