/**
 * The sky's prefiltered environment map (PMREM), computed on the CPU from the procedural sky.
 *
 * The sky is a zenith-to-horizon gradient, a warm glow around the sun and a dark ground (no
 * downloaded HDR). three's `PMREMGenerator` would render it into a 256² cube and filter every
 * texel with 256 GGX samples on the GPU: about 2 s of software WebGL (SwiftShader) before the
 * first tree could be drawn. The sky is a smooth analytic function, so the same map is computed
 * here directly, in 45–60 ms cold (15 ms warm): every mip level holds the sky's radiance
 * filtered by the GGX lobe of that level's roughness (three's `PMREMGenerator.lodToRoughness`, the view along the normal,
 * Karis's split-sum prefilter with Hammersley samples), the roughest level being the irradiance
 * that three's standard material reads (`getIBLIrradiance`). The texture is a half-float cube
 * with explicit mip levels flagged as a PMREM, so three samples it exactly as its own.
 */
import type { Color, Vector3 } from 'three';
import {
  CompressedCubeTexture,
  DataUtils,
  HalfFloatType,
  LinearFilter,
  LinearMipmapLinearFilter,
  LinearSRGBColorSpace,
  RGBAFormat,
  type CompressedPixelFormat,
  type CompressedTextureMipmap,
} from 'three';

/** The procedural sky: linear colours and the direction toward the sun (world, y up). */
export interface Sky {
  zenith: Color;
  horizon: Color;
  ground: Color;
  /** Colour of the glow around the sun (linear, already scaled). */
  sunGlow: Color;
  sunDirection: Vector3;
}

/** Face size (texels) of the sharpest level; each level halves it. */
export const SKY_FACE_SIZE = 64;
/** Face size of the roughest level (three's PMREM stops at 8² faces too). */
const SKY_MIN_FACE_SIZE = 8;
/** Hammersley samples per texel for each level after the first (which needs none). */
const SAMPLES_PER_LEVEL = [0, 16, 32, 256];

/** Radiance of `sky` toward the unit direction (dx, dy, dz), written into `out` (rgb). */
export function skyRadiance(sky: Sky, dx: number, dy: number, dz: number, out: number[]): void {
  if (dy >= 0) {
    // Gradient: horizon to zenith by up^0.6, then the glow, 0.6 sun^8 + 4 sun^256.
    const t = Math.pow(Math.min(dy, 1), 0.6);
    const s = sky.sunDirection;
    const sun = Math.max(dx * s.x + dy * s.y + dz * s.z, 0);
    const s2 = sun * sun;
    const s8 = s2 * s2 * s2 * s2;
    let s256 = s8;
    for (let i = 0; i < 5; i++) s256 *= s256;
    const glow = 0.6 * s8 + 4 * s256;
    out[0] = sky.horizon.r + (sky.zenith.r - sky.horizon.r) * t + sky.sunGlow.r * glow;
    out[1] = sky.horizon.g + (sky.zenith.g - sky.horizon.g) * t + sky.sunGlow.g * glow;
    out[2] = sky.horizon.b + (sky.zenith.b - sky.horizon.b) * t + sky.sunGlow.b * glow;
  } else {
    // Ground: from 0.6 of the horizon at the horizon to the ground colour 14° below.
    const t = Math.min(-dy * 4, 1);
    out[0] = sky.horizon.r * 0.6 + (sky.ground.r - sky.horizon.r * 0.6) * t;
    out[1] = sky.horizon.g * 0.6 + (sky.ground.g - sky.horizon.g * 0.6) * t;
    out[2] = sky.horizon.b * 0.6 + (sky.ground.b - sky.horizon.b * 0.6) * t;
  }
}

/**
 * The world direction of texel (i, j) of cube face `face` (0..5: +X, -X, +Y, -Y, +Z, -Z) of
 * `size`² texels, as three samples a cube texture that is not a render target: it looks up the
 * direction with x negated (`WebGLMaterials`' flip), and the face and texel follow OpenGL's cube
 * map table (row j is the t coordinate). Written into `out` (unit length).
 */
export function texelDirection(
  face: number,
  i: number,
  j: number,
  size: number,
  out: Vector3,
): Vector3 {
  const [x, y, z] = texelUnit(face, i, j, size);
  return out.set(x, y, z);
}

/** three's roughness of mip level `lod` of `maxLod` (`PMREMGenerator.lodToRoughness`). */
export function lodToRoughness(lod: number, maxLod: number): number {
  return maxLod > 0 ? 1 - Math.sqrt(1 - lod / maxLod) : 0;
}

/** Van der Corput radical inverse in base 2 (the Hammersley sequence's second coordinate). */
function radicalInverse(i: number): number {
  let bits = i >>> 0;
  bits = ((bits << 16) | (bits >>> 16)) >>> 0;
  bits = (((bits & 0x55555555) << 1) | ((bits & 0xaaaaaaaa) >>> 1)) >>> 0;
  bits = (((bits & 0x33333333) << 2) | ((bits & 0xcccccccc) >>> 2)) >>> 0;
  bits = (((bits & 0x0f0f0f0f) << 4) | ((bits & 0xf0f0f0f0) >>> 4)) >>> 0;
  bits = (((bits & 0x00ff00ff) << 8) | ((bits & 0xff00ff00) >>> 8)) >>> 0;
  return bits / 4294967296;
}

/**
 * The prefiltered sky: `levels[lod][face]` is an RGBA float array of that level's face (row
 * after row), face sizes SKY_FACE_SIZE, /2, ... down to 8.
 *
 * It runs once per page, cold, on the main thread before the first tree can be drawn, so its
 * loops work on plain numbers: the texel direction ([`texelUnit`]) and the frame around it
 * (three's `cross` and `normalize`, written out) take the same operations in the same order as
 * three's vectors, so every value is the same to the bit (tested against the composition with
 * three's vectors). Run cold in a fresh Node process that took it from about 90 ms to 45–60 ms.
 */
export function prefilterSky(sky: Sky): Float32Array[][] {
  const sizes: number[] = [];
  for (let s = SKY_FACE_SIZE; s >= SKY_MIN_FACE_SIZE; s >>= 1) sizes.push(s);
  const maxLod = sizes.length - 1;
  const rgb = [0, 0, 0];
  return sizes.map((size, lod) => {
    const roughness = lodToRoughness(lod, maxLod);
    const alpha = roughness * roughness;
    const samples = SAMPLES_PER_LEVEL[lod] ?? 256;
    // The half vectors' (cos θ, sin θ cos φ, sin θ sin φ) in the normal's frame, the same for
    // every texel (GGX importance sampling, Hammersley points).
    const cosT = new Float64Array(samples);
    const st = new Float64Array(samples);
    const sb = new Float64Array(samples);
    for (let k = 0; k < samples; k++) {
      const u = k / samples;
      const c = Math.sqrt((1 - u) / (1 + (alpha * alpha - 1) * u));
      const phi = 2 * Math.PI * radicalInverse(k);
      const sinT = Math.sqrt(Math.max(0, 1 - c * c));
      cosT[k] = c;
      st[k] = sinT * Math.cos(phi);
      sb[k] = sinT * Math.sin(phi);
    }
    const faces: Float32Array[] = [];
    for (let face = 0; face < 6; face++) {
      const data = new Float32Array(size * size * 4);
      for (let j = 0; j < size; j++) {
        for (let i = 0; i < size; i++) {
          const o = (j * size + i) * 4;
          const n = texelUnit(face, i, j, size);
          if (samples === 0) {
            skyRadiance(sky, n[0], n[1], n[2], rgb);
            data[o] = rgb[0]!;
            data[o + 1] = rgb[1]!;
            data[o + 2] = rgb[2]!;
          } else {
            filterTexel(sky, n, cosT, st, sb, data, o);
          }
          data[o + 3] = 1;
        }
      }
      faces.push(data);
    }
    return faces;
  });
}

/** Scratch of [`filterTexel`]'s radiance. */
const RADIANCE = [0, 0, 0];

/** Scratch of [`texelUnit`]. */
const UNIT: [number, number, number] = [0, 0, 0];

/** [`texelDirection`] as three numbers (the array is reused). */
function texelUnit(face: number, i: number, j: number, size: number): [number, number, number] {
  const sc = (2 * (i + 0.5)) / size - 1;
  const tc = (2 * (j + 0.5)) / size - 1;
  let x: number, y: number, z: number;
  if (face === 0) [x, y, z] = [-1, -tc, -sc];
  else if (face === 1) [x, y, z] = [1, -tc, sc];
  else if (face === 2) [x, y, z] = [-sc, 1, tc];
  else if (face === 3) [x, y, z] = [-sc, -1, -tc];
  else if (face === 4) [x, y, z] = [-sc, -tc, 1];
  else [x, y, z] = [sc, -tc, -1];
  // three's normalize: multiplyScalar(1 / (length() || 1)).
  const inv = 1 / (Math.sqrt(x * x + y * y + z * z) || 1);
  UNIT[0] = x * inv;
  UNIT[1] = y * inv;
  UNIT[2] = z * inv;
  return UNIT;
}

/**
 * One texel of a rough level: the sky's radiance along L = 2 (N·H) H − N for every half vector
 * H of the level, weighted by N·L, written into `data` at `o` (rgb).
 */
function filterTexel(
  sky: Sky,
  n: readonly number[],
  cosT: Float64Array,
  st: Float64Array,
  sb: Float64Array,
  data: Float32Array,
  o: number,
): void {
  const [nx, ny, nz] = n as [number, number, number];
  // A frame around the normal: three's tangent.set(...).cross(n).normalize() and
  // bitangent.crossVectors(n, tangent).
  const ax = Math.abs(ny) < 0.999 ? 0 : 1;
  const ay = Math.abs(ny) < 0.999 ? 1 : 0;
  let tx = ay * nz - 0 * ny;
  let ty = 0 * nx - ax * nz;
  let tz = ax * ny - ay * nx;
  const inv = 1 / (Math.sqrt(tx * tx + ty * ty + tz * tz) || 1);
  tx *= inv;
  ty *= inv;
  tz *= inv;
  const bx = ny * tz - nz * ty;
  const by = nz * tx - nx * tz;
  const bz = nx * ty - ny * tx;
  const rgb = RADIANCE;
  let r = 0;
  let g = 0;
  let b = 0;
  let weight = 0;
  for (let k = 0; k < cosT.length; k++) {
    const c = cosT[k]!;
    const hx = tx * st[k]! + bx * sb[k]! + nx * c;
    const hy = ty * st[k]! + by * sb[k]! + ny * c;
    const hz = tz * st[k]! + bz * sb[k]! + nz * c;
    const nl = 2 * c * c - 1;
    if (nl <= 0) continue;
    skyRadiance(sky, 2 * c * hx - nx, 2 * c * hy - ny, 2 * c * hz - nz, rgb);
    r += rgb[0]! * nl;
    g += rgb[1]! * nl;
    b += rgb[2]! * nl;
    weight += nl;
  }
  data[o] = r / weight;
  data[o + 1] = g / weight;
  data[o + 2] = b / weight;
}

/**
 * The prefiltered sky as a texture three uses as a PMREM environment (`scene.environment`):
 * a half-float cube, every level given. Each call makes a new texture (the caller disposes it).
 */
export function skyEnvironmentTexture(levels: Float32Array[][]): CompressedCubeTexture {
  const half = levels.map((faces) =>
    faces.map((data) => {
      const out = new Uint16Array(data.length);
      for (let k = 0; k < data.length; k++) out[k] = DataUtils.toHalfFloat(data[k]!);
      return out;
    }),
  );
  const images = [0, 1, 2, 3, 4, 5].map((face) => {
    const mipmaps: CompressedTextureMipmap[] = half.map((faces) => {
      const size = Math.round(Math.sqrt(faces[face]!.length / 4));
      return { data: faces[face]!, width: size, height: size };
    });
    return { width: SKY_FACE_SIZE, height: SKY_FACE_SIZE, mipmaps };
  });
  const texture = new CompressedCubeTexture(
    images,
    // Uncompressed RGBA: three uploads each level with texSubImage2D.
    RGBAFormat as unknown as CompressedPixelFormat,
    HalfFloatType,
  );
  texture.name = 'Sylva sky PMREM';
  texture.isPMREMTexture = true;
  texture.colorSpace = LinearSRGBColorSpace;
  texture.minFilter = LinearMipmapLinearFilter;
  texture.magFilter = LinearFilter;
  texture.generateMipmaps = false;
  texture.needsUpdate = true;
  return texture;
}
