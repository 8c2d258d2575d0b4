/**
 * The impostor of the LOD export as a GLB any glTF viewer or engine draws without Sylva's shader
 * (docs/formats.md, LOD zip):
 *
 * * **Image**: the whole hemi-octahedral colour atlas (`impostor.ts`, `hemiOct.ts`) as one PNG,
 *   the `baseColorTexture` of material `impostor` (alpha MASK, metallic 0, roughness 1).
 * * **Mesh**: crossed quads through the centre of the tree's bounding sphere, one per horizon
 *   view of the atlas at the four corners of the grid (+X, +Z, −X, −Z): each quad faces its
 *   view direction, one-sided, is `2 · radius` wide and tall and maps exactly its frame of the
 *   atlas (the orthographic image of the tree from that side), so seen from any side the two
 *   planes show the tree from the nearest corner views. Back to back quads sit `0.002 · radius`
 *   apart so that an importer that draws both sides shows the front one. Their normals are the
 *   view direction tilted 45° up (`normalize(d + Y)`): lit like a crown's top-lit average, not
 *   like a wall facing sideways (which the sun grazes).
 * * **Extras**: `extras.sylva_impostor` on the node describes the whole atlas (frame grid,
 *   layout, each frame's view direction, the projection) so an engine with an
 *   octahedral-impostor shader can use the image as it is; `extras.sylva_lod` the screen sizes;
 *   `extras.bounds` the tree's box.
 *
 * No glTF extension is used. Positions in metres, Y up, as the level GLBs.
 */
import { frameDirection, viewBasis, type Vec3 } from './hemiOct';

/** What the impostor GLB is made of. */
export interface ImpostorGlbInput {
  /** File stem: the node is `<name>_impostor` under root `<name>`. */
  name: string;
  /** The colour atlas as a PNG (top row first, straight alpha). */
  png: Uint8Array;
  /** Frames per side of the atlas. */
  frames: number;
  /** Pixels per frame side. */
  cellPx: number;
  /** Bounding sphere the frames were fitted to (tree space, metres). */
  centre: Vec3;
  radius: number;
  /** The tree's box (bark and leaves). */
  bounds: { min: Vec3; max: Vec3 };
  /** Screen sizes below which LOD0, LOD1, LOD2 give way (the impostor below the last). */
  screenSizes: readonly number[];
  /** `asset.generator`. */
  generator: string;
  /** The tree's content hash. */
  hash: string;
}

/** Alpha cutoff of the MASK material: the atlas alpha is the share of a texel the tree covers. */
export const IMPOSTOR_ALPHA_CUTOFF = 0.35;

/** The atlas frames the crossed quads show: the grid's corners, the +X, +Z, −X, −Z views. */
export function crossFrames(n: number): [number, number][] {
  return [
    [n - 1, n - 1],
    [n - 1, 0],
    [0, 0],
    [0, n - 1],
  ];
}

/** The frame (i, j) rectangle in glTF UVs (v down): `[u0, v0, u1, v1]`, v0 at the image top. */
export function frameUv(i: number, j: number, n: number): [number, number, number, number] {
  // The atlas rows are written top first, so GL row j (from the bottom) is n - 1 - j from the top.
  return [i / n, (n - 1 - j) / n, (i + 1) / n, (n - j) / n];
}

/** Vertices of the crossed quads: positions, normals, UVs, and the triangle list. */
export function crossQuads(input: Pick<ImpostorGlbInput, 'frames' | 'centre' | 'radius'>): {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint16Array;
} {
  const { frames: n, centre, radius: r } = input;
  const quads = crossFrames(n);
  const positions = new Float32Array(quads.length * 12);
  const normals = new Float32Array(quads.length * 12);
  const uvs = new Float32Array(quads.length * 8);
  const indices = new Uint16Array(quads.length * 6);
  quads.forEach(([i, j], q) => {
    const d = frameDirection(i, j, n);
    const tilt = Math.hypot(d[0], d[1] + 1, d[2]);
    const normal = [d[0] / tilt, (d[1] + 1) / tilt, d[2] / tilt];
    const { right, up } = viewBasis(d);
    const [u0, v0, u1, v1] = frameUv(i, j, n);
    // Counter-clockwise seen from d (right × up = d): bottom left, bottom right, top right, top left.
    const corners: [number, number, number, number][] = [
      [-1, -1, u0, v1],
      [1, -1, u1, v1],
      [1, 1, u1, v0],
      [-1, 1, u0, v0],
    ];
    corners.forEach(([s, t, u, v], k) => {
      const o = (q * 4 + k) * 3;
      for (let a = 0; a < 3; a++) {
        positions[o + a] = centre[a]! + (right[a]! * s + up[a]! * t) * r + d[a]! * 0.002 * r;
        normals[o + a] = normal[a]!;
      }
      uvs[(q * 4 + k) * 2] = u;
      uvs[(q * 4 + k) * 2 + 1] = v;
    });
    indices.set(
      [0, 1, 2, 0, 2, 3].map((x) => x + q * 4),
      q * 6,
    );
  });
  return { positions, normals, uvs, indices };
}

/** The node's `extras` (module docs; docs/formats.md lists every field). */
export function impostorExtras(input: ImpostorGlbInput): Record<string, unknown> {
  const n = input.frames;
  const round = (x: number) => Math.round(x * 1e6) / 1e6;
  const vec = (v: readonly number[]) => v.map(round);
  const directions: number[][] = [];
  for (let i = 0; i < n; i++)
    for (let j = 0; j < n; j++) directions.push(vec(frameDirection(i, j, n)));
  return {
    sylva_impostor: {
      layout: 'hemi-octahedral',
      frames: n,
      frame_px: input.cellPx,
      atlas_px: n * input.cellPx,
      image: 0,
      centre: vec(input.centre),
      radius: round(input.radius),
      frame_uv:
        'frame (i, j) covers u in [i/n, (i+1)/n] and v in [(n-1-j)/n, (n-j)/n] (glTF UV, v from the image top)',
      direction:
        'frame (i, j) is the view from unit direction d(i, j) = hemi-oct decode(i/(n-1), j/(n-1)): a = 2u-1, b = 2v-1, x = (a+b)/2, z = (a-b)/2, y = 1-|x|-|z|, normalised (Y up; +X at (n-1, n-1), +Z at (n-1, 0), -X at (0, 0), -Z at (0, n-1), the zenith at the centre)',
      directions,
      directions_order: 'index i * n + j',
      projection:
        'orthographic along -d onto a square of side 2 * radius centred on centre, image right = normalize(Y x d), image up = d x right (straight above: right = +X)',
      color: 'unlit albedo (sRGB), alpha = the share of the texel the tree covers',
      crossed_quads: crossFrames(n).map(([i, j]) => ({
        frame: [i, j],
        direction: vec(frameDirection(i, j, n)),
      })),
    },
    sylva_lod: {
      level: 3,
      screen_sizes: [...input.screenSizes],
      screen_size: 0,
      shown_below: input.screenSizes.at(-1) ?? 0,
      measure:
        "screen size = bounding radius / (distance * tan(vertical fov / 2)), about the tree's height on screen over the screen height; the impostor is shown below the last screen size",
    },
    bounds: { min: vec(input.bounds.min), max: vec(input.bounds.max) },
  };
}

/** Pads `bytes` with `fill` to a multiple of 4. */
function pad4(bytes: Uint8Array, fill: number): Uint8Array {
  const out = new Uint8Array(Math.ceil(bytes.length / 4) * 4).fill(fill);
  out.set(bytes);
  return out;
}

/** The impostor GLB (module docs). */
export function impostorGlb(input: ImpostorGlbInput): Uint8Array {
  const quads = crossQuads(input);
  const parts: Uint8Array[] = [];
  const views: Record<string, number>[] = [];
  let offset = 0;
  const addView = (bytes: Uint8Array, target?: number): number => {
    views.push({
      buffer: 0,
      byteOffset: offset,
      byteLength: bytes.length,
      ...(target ? { target } : {}),
    });
    const padded = pad4(bytes, 0);
    parts.push(padded);
    offset += padded.length;
    return views.length - 1;
  };
  const bytesOf = (a: Float32Array | Uint16Array) =>
    new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
  const count = quads.positions.length / 3;
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let v = 0; v < count; v++) {
    for (let a = 0; a < 3; a++) {
      lo[a] = Math.min(lo[a]!, quads.positions[v * 3 + a]!);
      hi[a] = Math.max(hi[a]!, quads.positions[v * 3 + a]!);
    }
  }
  const accessors = [
    {
      bufferView: addView(bytesOf(quads.positions), 34962),
      componentType: 5126,
      count,
      type: 'VEC3',
      min: lo.map(Math.fround),
      max: hi.map(Math.fround),
    },
    {
      bufferView: addView(bytesOf(quads.normals), 34962),
      componentType: 5126,
      count,
      type: 'VEC3',
    },
    { bufferView: addView(bytesOf(quads.uvs), 34962), componentType: 5126, count, type: 'VEC2' },
    {
      bufferView: addView(bytesOf(quads.indices), 34963),
      componentType: 5123,
      count: quads.indices.length,
      type: 'SCALAR',
    },
  ];
  const image = addView(input.png);
  const json = {
    asset: { version: '2.0', generator: input.generator },
    scene: 0,
    scenes: [{ nodes: [0], extras: { sylva_hash: input.hash } }],
    nodes: [
      { name: input.name, children: [1] },
      { name: `${input.name}_impostor`, mesh: 0, extras: impostorExtras(input) },
    ],
    meshes: [
      {
        name: 'impostor',
        primitives: [
          { attributes: { POSITION: 0, NORMAL: 1, TEXCOORD_0: 2 }, indices: 3, material: 0 },
        ],
      },
    ],
    materials: [
      {
        name: 'impostor',
        pbrMetallicRoughness: {
          baseColorTexture: { index: 0 },
          metallicFactor: 0,
          roughnessFactor: 1,
        },
        alphaMode: 'MASK',
        alphaCutoff: IMPOSTOR_ALPHA_CUTOFF,
      },
    ],
    // Clamped: a frame's edge must not sample the opposite side of the atlas.
    samplers: [{ magFilter: 9729, minFilter: 9987, wrapS: 33071, wrapT: 33071 }],
    textures: [{ sampler: 0, source: 0 }],
    images: [{ name: 'impostor_atlas', mimeType: 'image/png', bufferView: image }],
    accessors,
    bufferViews: views,
    buffers: [{ byteLength: offset }],
  };
  const text = pad4(new TextEncoder().encode(JSON.stringify(json)), 0x20);
  const total = 12 + 8 + text.length + 8 + offset;
  const glb = new Uint8Array(total);
  const view = new DataView(glb.buffer);
  view.setUint32(0, 0x46546c67, true); // 'glTF'
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, text.length, true);
  view.setUint32(16, 0x4e4f534a, true); // 'JSON'
  glb.set(text, 20);
  let at = 20 + text.length;
  view.setUint32(at, offset, true);
  view.setUint32(at + 4, 0x004e4942, true); // 'BIN\0'
  at += 8;
  for (const p of parts) {
    glb.set(p, at);
    at += p.length;
  }
  return glb;
}
