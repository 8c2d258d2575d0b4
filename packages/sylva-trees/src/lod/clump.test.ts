import { describe, expect, it } from 'vitest';
import { CELL_DENSITY, CLUMP_SIZE, clumpAtlas, clumpLeaves, densityCell } from './clump';

/** An elliptic leaf `w`×`h` texels, green, transparent around it. */
function leaf(w = 64, h = 128): { width: number; height: number; rgba: Uint8Array } {
  const rgba = new Uint8Array(w * h * 4);
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      const i = (y * w + x) * 4;
      const inside = ((x + 0.5) / w - 0.5) ** 2 + ((y + 0.5) / h - 0.5) ** 2 < 0.25;
      rgba.set(inside ? [50, 140, 30, 255] : [0, 0, 0, 0], i);
    }
  }
  return { width: w, height: h, rgba };
}

/** Share of the opaque texels (alpha >= 128) of atlas cell `cell` (rows bottom-up). */
function coverage(atlas: Uint8Array, cell: number, size = CLUMP_SIZE): number {
  const half = size / 2;
  const [x0, y0] = [(cell % 2) * half, Math.floor(cell / 2) * half];
  let n = 0;
  for (let y = y0; y < y0 + half; y++) {
    for (let x = x0; x < x0 + half; x++) if (atlas[(y * size + x) * 4 + 3]! >= 128) n++;
  }
  return n / (half * half);
}

describe('clumpAtlas', () => {
  it('fills each cell as densely as its density asks, densest last', () => {
    const atlas = clumpAtlas(leaf(), 7);
    expect(atlas.length).toBe(CLUMP_SIZE * CLUMP_SIZE * 4);
    const c = [0, 1, 2, 3].map((k) => coverage(atlas, k));
    for (let k = 1; k < 4; k++) expect(c[k]!).toBeGreaterThan(c[k - 1]!);
    // The leaves fill a disc of 0.4 of the cell's half-width: at most pi 0.4² = 0.5 of it.
    expect(c[0]!).toBeGreaterThan(0.01);
    expect(c[3]!).toBeLessThan(0.55);
    expect(c[3]!).toBeGreaterThan(0.25);
  });

  it('draws the leaf in its own colour and bleeds it into the transparent texels', () => {
    const atlas = clumpAtlas(leaf(), 7);
    let opaque = 0;
    for (let i = 0; i < atlas.length; i += 4) {
      // Every texel, seen or not, is the leaf's green (mipmaps never average in black).
      expect(atlas[i + 1]!).toBeGreaterThan(atlas[i]!);
      expect(atlas[i + 1]!).toBeGreaterThan(100);
      if (atlas[i + 3] === 255) opaque++;
    }
    expect(opaque).toBeGreaterThan(1000);
  });

  it('is the same for the same seed and differs for another', () => {
    const a = clumpAtlas(leaf(), 7);
    expect(clumpAtlas(leaf(), 7)).toEqual(a);
    expect(clumpAtlas(leaf(), 8)).not.toEqual(a);
  });

  it('draws green ellipses for a tree without a leaf texture', () => {
    const atlas = clumpAtlas(null, 7, 128);
    expect(coverage(atlas, 3, 128)).toBeGreaterThan(0.2);
  });

  it('keeps the densities and counts the cloud geometry picks cells by', () => {
    expect(CELL_DENSITY.map((d) => densityCell(d))).toEqual([0, 1, 2, 3]);
    expect(densityCell(0.01)).toBe(0);
    expect(densityCell(0.7)).toBe(2);
    expect([0, 1, 2, 3].map(clumpLeaves)).toEqual([15, 40, 93, 360]);
  });
});
