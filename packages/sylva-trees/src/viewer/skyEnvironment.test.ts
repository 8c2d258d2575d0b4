/** The sky's prefiltered environment map, computed on the CPU (skyEnvironment.ts). */
import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { SKY, skyEnvironment } from './lighting';
import {
  SKY_FACE_SIZE,
  lodToRoughness,
  prefilterSky,
  skyRadiance,
  texelDirection,
} from './skyEnvironment';

const levels = prefilterSky(SKY);
const maxLod = levels.length - 1;

/**
 * What three reads from level `lod` toward the world direction `d`: it negates x for a cube
 * texture that is not a render target, then OpenGL picks the face and texel (its cube map table,
 * written out here independently of `texelDirection`). Nearest texel, rgb.
 */
function lookup(lod: number, d: Vector3): number[] {
  const [gx, gy, gz] = [-d.x, d.y, d.z];
  const ax = Math.abs(gx);
  const ay = Math.abs(gy);
  const az = Math.abs(gz);
  let face: number, sc: number, tc: number, ma: number;
  if (ax >= ay && ax >= az) [face, sc, tc, ma] = gx > 0 ? [0, -gz, -gy, ax] : [1, gz, -gy, ax];
  else if (ay >= az) [face, sc, tc, ma] = gy > 0 ? [2, gx, gz, ay] : [3, gx, -gz, ay];
  else [face, sc, tc, ma] = gz > 0 ? [4, gx, -gy, az] : [5, -gx, -gy, az];
  const data = levels[lod]![face]!;
  const size = Math.round(Math.sqrt(data.length / 4));
  const i = Math.min(size - 1, Math.floor(((sc / ma + 1) / 2) * size));
  const j = Math.min(size - 1, Math.floor(((tc / ma + 1) / 2) * size));
  const o = (j * size + i) * 4;
  return [data[o]!, data[o + 1]!, data[o + 2]!];
}

const radiance = (d: Vector3): number[] => {
  const out = [0, 0, 0];
  skyRadiance(SKY, d.x, d.y, d.z, out);
  return out;
};
const luminance = ([r, g, b]: number[]) => 0.2126 * r! + 0.7152 * g! + 0.0722 * b!;

describe('the sky environment', () => {
  it('has levels from 64² down to 8², with three’s roughness per level', () => {
    expect(levels.map((faces) => Math.sqrt(faces[0]!.length / 4))).toEqual([64, 32, 16, 8]);
    expect(levels.every((faces) => faces.length === 6)).toBe(true);
    expect(SKY_FACE_SIZE).toBe(64);
    expect(lodToRoughness(0, maxLod)).toBe(0);
    expect(lodToRoughness(maxLod, maxLod)).toBe(1);
    const bad = levels.flat().filter((data) => data.some((v) => !Number.isFinite(v) || v < 0));
    expect(bad).toHaveLength(0);
  });

  it('puts every direction where three looks it up (level 0 is the sky itself)', () => {
    // Directions at texel centres of level 0 (so the nearest texel is exact), on all faces.
    const d = new Vector3();
    for (let face = 0; face < 6; face++) {
      for (const [i, j] of [
        [3, 5],
        [60, 2],
        [31, 40],
        [10, 58],
      ] as const) {
        texelDirection(face, i, j, 64, d);
        const got = lookup(0, d);
        const want = radiance(d);
        for (let c = 0; c < 3; c++) expect(got[c]).toBeCloseTo(want[c]!, 5);
      }
    }
  });

  it('shows the sun glow toward the sun and nowhere else, on both sides of the x flip', () => {
    const toSun = SKY.sunDirection.clone();
    const mirrored = new Vector3(-toSun.x, toSun.y, toSun.z);
    expect(luminance(lookup(0, toSun))).toBeGreaterThan(2 * luminance(lookup(0, mirrored)));
    // Still warmer toward the sun on the roughest level (the irradiance three reads).
    expect(luminance(lookup(maxLod, toSun))).toBeGreaterThan(luminance(lookup(maxLod, mirrored)));
  });

  it('is sky above, ground below, and smooth where it is rough', () => {
    const up = new Vector3(0, 1, 0);
    const down = new Vector3(0, -1, 0);
    for (let lod = 0; lod <= maxLod; lod++) {
      const sky = lookup(lod, up);
      expect(sky[2]).toBeGreaterThan(sky[0]!); // blue zenith
      expect(luminance(sky)).toBeGreaterThan(2 * luminance(lookup(lod, down)));
    }
    // The irradiance level is the cosine-weighted mean: straight up it lies between the zenith
    // and the horizon, and neighbouring texels differ little (no sampling blotches).
    const irradianceUp = luminance(lookup(maxLod, up));
    expect(irradianceUp).toBeLessThan(luminance(radiance(up)) * 1.3);
    expect(irradianceUp).toBeGreaterThan(
      luminance(radiance(new Vector3(1, 0.01, 0).normalize())) * 0.5,
    );
    const top = levels[maxLod]![2]!;
    for (let k = 4; k < top.length - 4; k += 4) {
      if ((k / 4) % 8 === 7) continue; // row end
      expect(Math.abs(top[k]! - top[k + 4]!)).toBeLessThan(0.08 * top[k]!);
    }
  });

  it('is a half-float cube texture three uses as its own PMREM', () => {
    const texture = skyEnvironment();
    expect(texture.isPMREMTexture).toBe(true);
    expect((texture as unknown as { isCubeTexture: boolean }).isCubeTexture).toBe(true);
    const images = texture.image as {
      mipmaps: { data: Uint16Array; width: number }[];
    }[];
    expect(images).toHaveLength(6);
    // three derives ENVMAP_MAX_LOD and ENVMAP_SIZE from the first face's levels.
    expect(images[0]!.mipmaps.map((m) => m.width)).toEqual([64, 32, 16, 8]);
    expect(images[0]!.mipmaps[0]!.data).toBeInstanceOf(Uint16Array);
    expect(texture.generateMipmaps).toBe(false);
    texture.dispose();
  });

  it('is, to the bit, the plain composition of texelDirection, the frame and skyRadiance', () => {
    expect(levels).toEqual(referencePrefilter());
  });
});

/** Van der Corput radical inverse in base 2, written with arithmetic (not bit tricks). */
function vanDerCorput(i: number): number {
  let x = 0;
  let f = 0.5;
  for (let k = i; k > 0; k = Math.floor(k / 2), f /= 2) x += (k % 2) * f;
  return x;
}

/** The prefilter as the plain composition of its parts (three's vectors, skyRadiance). */
function referencePrefilter(): Float32Array[][] {
  const sizes = [64, 32, 16, 8];
  const samplesOf = [0, 16, 32, 256];
  const n = new Vector3();
  const tangent = new Vector3();
  const bitangent = new Vector3();
  const rgb = [0, 0, 0];
  return sizes.map((size, lod) => {
    const alpha = lodToRoughness(lod, 3) ** 2;
    const samples = samplesOf[lod]!;
    const faces: Float32Array[] = [];
    for (let face = 0; face < 6; face++) {
      const data = new Float32Array(size * size * 4);
      for (let j = 0; j < size; j++) {
        for (let i = 0; i < size; i++) {
          texelDirection(face, i, j, size, n);
          let [r, g, b] = [0, 0, 0];
          if (samples === 0) {
            skyRadiance(SKY, n.x, n.y, n.z, rgb);
            [r, g, b] = rgb as [number, number, number];
          } else {
            const up = Math.abs(n.y) < 0.999;
            tangent
              .set(up ? 0 : 1, up ? 1 : 0, 0)
              .cross(n)
              .normalize();
            bitangent.crossVectors(n, tangent);
            let weight = 0;
            for (let k = 0; k < samples; k++) {
              const u = k / samples;
              const c = Math.sqrt((1 - u) / (1 + (alpha * alpha - 1) * u));
              const phi = 2 * Math.PI * vanDerCorput(k);
              const sinT = Math.sqrt(Math.max(0, 1 - c * c));
              const h = tangent
                .clone()
                .multiplyScalar(sinT * Math.cos(phi))
                .add(bitangent.clone().multiplyScalar(sinT * Math.sin(phi)))
                .add(n.clone().multiplyScalar(c));
              const nl = 2 * c * c - 1;
              if (nl <= 0) continue;
              skyRadiance(SKY, 2 * c * h.x - n.x, 2 * c * h.y - n.y, 2 * c * h.z - n.z, rgb);
              r += rgb[0]! * nl;
              g += rgb[1]! * nl;
              b += rgb[2]! * nl;
              weight += nl;
            }
            [r, g, b] = [r / weight, g / weight, b / weight];
          }
          data.set([r, g, b, 1], (j * size + i) * 4);
        }
      }
      faces.push(data);
    }
    return faces;
  });
}
