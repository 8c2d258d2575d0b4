import { NoColorSpace, RepeatWrapping, SRGBColorSpace, type DataTexture } from 'three';
import { describe, expect, it } from 'vitest';
import { loadWasm } from '../testing/realWasm';
import { barkOf } from '../worker/generate';
import { BARK_FLAT_COLOR, BARK_REPEAT, BarkTextures, createBarkMaterial } from './barkMaterial';
import { createBarkLookUniforms } from './barkLook';

describe('bark material', () => {
  it('uses the core-baked maps: sRGB colour, linear normal map, repeating, mipmapped', () => {
    const bark = barkOf(loadWasm(), 1);
    if (!bark) throw new Error('this wasm build has no bark_maps');
    expect(bark.size).toBe(256);
    expect(bark.kind).toBe(1);
    const material = createBarkMaterial();
    const look = createBarkLookUniforms();
    const textures = new BarkTextures(material, look);
    expect(textures.size).toBeNull();
    textures.set(bark);
    expect(textures.size).toEqual({ width: 256, height: 256 });
    const map = material.map as DataTexture;
    const normal = material.normalMap as DataTexture;
    expect(map.image.data).toBe(bark.color); // wrapped, not copied
    expect(normal.image.data).toBe(bark.normal);
    // Occlusion-roughness-metal: the roughness slot (G); the type's style reaches the bark look.
    expect(material.aoMap).toBeNull();
    expect((material.roughnessMap as DataTexture).image.data).toBe(bark.orm);
    expect(textures.kind).toBe(1);
    expect(look.uBarkTile.value).toBeCloseTo(bark.style.tile_at_1m);
    expect(look.uBarkYoungRadius.value).toBeCloseTo(bark.style.young_radius);
    expect(map.colorSpace).toBe(SRGBColorSpace);
    expect(normal.colorSpace).toBe(NoColorSpace);
    for (const t of [map, normal]) {
      expect([t.wrapS, t.wrapT]).toEqual([RepeatWrapping, RepeatWrapping]);
      // Integer repeat around the stem (the seam at u = 1 matches u = 0), square texels along.
      expect(Number.isInteger(t.repeat.x)).toBe(true);
      expect(t.repeat.x).toBe(BARK_REPEAT);
      expect(t.repeat.y).toBe(t.repeat.x);
      expect(t.generateMipmaps).toBe(true);
      expect(t.flipY).toBe(false);
    }
    expect(material.color.getHexString()).toBe('ffffff');
    // The maps have content: dark fissures and lighter plates, normals tilted both ways.
    let lo = 255;
    let hi = 0;
    for (let i = 0; i < bark.color.length; i += 4) {
      lo = Math.min(lo, bark.color[i] ?? 0);
      hi = Math.max(hi, bark.color[i] ?? 0);
    }
    expect(hi - lo).toBeGreaterThan(40);
    textures.dispose();
    expect(material.map).toBeNull();
    expect(material.normalMap).toBeNull();
    expect(`#${material.color.getHexString()}`).toBe(BARK_FLAT_COLOR);
  });

  it('ignores buffers of the wrong size', () => {
    const material = createBarkMaterial();
    const textures = new BarkTextures(material);
    const ok = new Uint8Array(16 * 16 * 4);
    const style = {
      tile_at_1m: 0.2,
      young_radius: 0.02,
      young_rgb: [0, 0, 0] as [number, number, number],
      relief: 1,
    };
    textures.set({ size: 16, kind: 0, color: new Uint8Array(10), normal: ok, orm: ok, style });
    expect(material.map).toBeNull();
    textures.set({ size: 16, kind: 0, color: ok, normal: ok, orm: new Uint8Array(3), style });
    expect(material.map).toBeNull();
    expect(textures.size).toBeNull();
  });
});
