/**
 * The impostor GLB of the LOD export (`impostorGlb.ts`), its atlas image (`impostorImage.ts`)
 * and the PNG encoder (`export/png.ts`): valid containers, accessors sized to their views, the
 * atlas embedded as the base colour texture, no glTF extension, quads mapped to their frames
 * (the Khronos validator runs on the exported file in e2e/tests/lodExport.spec.ts).
 */
import { unzlibSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { crc32, encodePng } from '../export/png';
import { frameDirection, viewBasis, type Vec3 } from './hemiOct';
import {
  crossFrames,
  crossQuads,
  frameUv,
  impostorGlb,
  type ImpostorGlbInput,
} from './impostorGlb';
import { atlasImage, downsample, powerOfTwoBelow } from './impostorImage';

const FRAMES = 4;
const CELL = 8;
const SIZE = FRAMES * CELL;

/** A premultiplied linear atlas, bottom row first: frame (i, j) has a disc of its own colour. */
function bakedPixels(): Uint8Array {
  const px = new Uint8Array(SIZE * SIZE * 4);
  for (let y = 0; y < SIZE; y++) {
    for (let x = 0; x < SIZE; x++) {
      const [i, j] = [Math.floor(x / CELL), Math.floor(y / CELL)];
      const [cx, cy] = [(x % CELL) - CELL / 2 + 0.5, (y % CELL) - CELL / 2 + 0.5];
      const a = Math.hypot(cx, cy) < CELL / 3 ? 255 : (x + y) % 7 === 0 ? 128 : 0;
      const o = (y * SIZE + x) * 4;
      px.set([(i * 60 * a) / 255, (j * 60 * a) / 255, (100 * a) / 255, a], o);
    }
  }
  return px;
}

function input(png: Uint8Array): ImpostorGlbInput {
  return {
    name: 'oak',
    png,
    frames: FRAMES,
    cellPx: CELL,
    centre: [0.5, 4, -0.25],
    radius: 5,
    bounds: { min: [-3, 0, -3.5], max: [4, 8, 3] },
    screenSizes: [0.6, 0.4, 0.28],
    generator: 'Sylva test',
    hash: 'abc',
  };
}

interface Gltf {
  asset: { version: string };
  extensionsUsed?: string[];
  extensionsRequired?: string[];
  accessors: { bufferView: number; componentType: number; count: number; type: string }[];
  bufferViews: { byteOffset: number; byteLength: number }[];
  buffers: { byteLength: number }[];
  images: { bufferView: number; mimeType: string }[];
  materials: { pbrMetallicRoughness: { baseColorTexture: { index: number } }; alphaMode: string }[];
  textures: { source: number }[];
  nodes: { name: string; mesh?: number; extras?: Record<string, Record<string, unknown>> }[];
}

/** The JSON and BIN chunks of a GLB, checking the container. */
function parse(glb: Uint8Array): { json: Gltf; bin: Uint8Array } {
  const view = new DataView(glb.buffer, glb.byteOffset, glb.byteLength);
  expect(view.getUint32(0, true)).toBe(0x46546c67);
  expect(view.getUint32(4, true)).toBe(2);
  expect(view.getUint32(8, true)).toBe(glb.length);
  const jsonLength = view.getUint32(12, true);
  expect(jsonLength % 4).toBe(0);
  expect(view.getUint32(16, true)).toBe(0x4e4f534a);
  const json = JSON.parse(new TextDecoder().decode(glb.subarray(20, 20 + jsonLength))) as Gltf;
  const binAt = 20 + jsonLength;
  expect(view.getUint32(binAt + 4, true)).toBe(0x004e4942);
  const bin = glb.subarray(binAt + 8, binAt + 8 + view.getUint32(binAt, true));
  expect(binAt + 8 + bin.length).toBe(glb.length);
  return { json, bin };
}

describe('PNG encoder', () => {
  it('CRC-32 of the check string', () => {
    expect(crc32(new TextEncoder().encode('123456789'))).toBe(0xcbf43926);
  });

  it('round-trips: chunks with their CRCs, IHDR, the Sub-filtered rows inflate back', () => {
    const [w, h] = [5, 3];
    const rgba = new Uint8Array(w * h * 4).map((_, i) => (i * 37) & 0xff);
    const png = encodePng(w, h, rgba);
    expect([...png.subarray(0, 8)]).toEqual([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
    const view = new DataView(png.buffer, png.byteOffset, png.byteLength);
    const chunks: Record<string, Uint8Array> = {};
    for (let at = 8; at < png.length;) {
      const length = view.getUint32(at);
      const type = new TextDecoder().decode(png.subarray(at + 4, at + 8));
      expect(view.getUint32(at + 8 + length)).toBe(crc32(png.subarray(at + 4, at + 8 + length)));
      chunks[type] = png.subarray(at + 8, at + 8 + length);
      at += 12 + length;
    }
    expect(Object.keys(chunks)).toEqual(['IHDR', 'IDAT', 'IEND']);
    const ihdr = new DataView(chunks.IHDR!.buffer, chunks.IHDR!.byteOffset, 13);
    expect([ihdr.getUint32(0), ihdr.getUint32(4), ...chunks.IHDR!.subarray(8)]).toEqual([
      w,
      h,
      8,
      6,
      0,
      0,
      0,
    ]);
    const raw = unzlibSync(chunks.IDAT!);
    expect(raw.length).toBe(h * (w * 4 + 1));
    const back = new Uint8Array(w * h * 4);
    for (let y = 0; y < h; y++) {
      expect(raw[y * (w * 4 + 1)]).toBe(1);
      for (let x = 0; x < w * 4; x++) {
        const left = x >= 4 ? back[y * w * 4 + x - 4]! : 0;
        back[y * w * 4 + x] = (raw[y * (w * 4 + 1) + 1 + x]! + left) & 0xff;
      }
    }
    expect(back).toEqual(rgba);
    expect(encodePng(w, h, rgba)).toEqual(png);
  });
});

describe('impostor atlas image', () => {
  it('flips to top row first, unpremultiplies to sRGB, fills uncovered texels', () => {
    const px = bakedPixels();
    const image = atlasImage(px, SIZE, FRAMES);
    // A fully covered texel of frame (3, 0) (bottom right in GL): top right after the flip.
    const glAt = ((CELL / 2) * SIZE + 3 * CELL + CELL / 2) * 4;
    const topAt = ((SIZE - 1 - CELL / 2) * SIZE + 3 * CELL + CELL / 2) * 4;
    expect(px[glAt + 3]).toBe(255);
    expect(image[topAt + 3]).toBe(255);
    // Linear 180/255 is sRGB 219 (0.858); 0 stays 0; 100/255 is 168 (0.659).
    expect([...image.subarray(topAt, topAt + 3)]).toEqual([219, 0, 168]);
    // A half-covered texel carries its straight colour; an uncovered one the frame's mean.
    for (let y = 0; y < SIZE; y++) {
      for (let x = 0; x < SIZE; x++) {
        const a = px[(y * SIZE + x) * 4 + 3]!;
        const t = ((SIZE - 1 - y) * SIZE + x) * 4;
        expect(image[t + 3]).toBe(a);
        if (Math.floor(x / CELL) === 3 && Math.floor(y / CELL) === 0 && a === 128) {
          expect(Math.abs(image[t]! - 219)).toBeLessThanOrEqual(2);
        }
        if (Math.floor(x / CELL) === 3 && Math.floor(y / CELL) === 0 && a === 0) {
          expect(Math.abs(image[t]! - 219)).toBeLessThanOrEqual(2);
          expect(Math.abs(image[t + 2]! - 168)).toBeLessThanOrEqual(2);
        }
      }
    }
  });
});

describe('atlas reduced to a power of two', () => {
  it('keeps frames apart, coverage and colour sums (area filter)', () => {
    expect([powerOfTwoBelow(1280), powerOfTwoBelow(1024), powerOfTwoBelow(1023)]).toEqual([
      1024, 1024, 512,
    ]);
    // 10 × 10, two frames across: the left one covered red, the right one empty.
    const px = new Uint8Array(10 * 10 * 4);
    for (let y = 0; y < 10; y++)
      for (let x = 0; x < 5; x++) px.set([200, 0, 0, 255], (y * 10 + x) * 4);
    const out = downsample(px, 10, 8);
    for (let y = 0; y < 8; y++) {
      for (let x = 0; x < 8; x++) {
        expect([...out.subarray((y * 8 + x) * 4, (y * 8 + x) * 4 + 4)]).toEqual(
          x < 4 ? [200, 0, 0, 255] : [0, 0, 0, 0],
        );
      }
    }
    // A one-texel stripe at column 2 of 5, reduced to 4: output texels 1 and 2 each cover half
    // of it, 0.5 of their 1.25 input texels: alpha 0.4 · 255 = 102.
    const stripe = new Uint8Array(5 * 5 * 4);
    for (let y = 0; y < 5; y++) stripe.set([255, 255, 255, 255], (y * 5 + 2) * 4);
    const small = downsample(stripe, 5, 4);
    expect([0, 1, 2, 3].map((x) => small[x * 4 + 3])).toEqual([0, 102, 102, 0]);
    expect(downsample(px, 10, 10)).toBe(px);
  });
});

describe('impostor GLB', () => {
  const png = encodePng(SIZE, SIZE, atlasImage(bakedPixels(), SIZE, FRAMES));
  const glb = impostorGlb(input(png));
  const { json, bin } = parse(glb);

  it('is glTF 2.0 with no extension, accessors sized to their views', () => {
    expect(json.asset.version).toBe('2.0');
    expect(json.extensionsUsed).toBeUndefined();
    expect(json.extensionsRequired).toBeUndefined();
    expect(json.buffers[0]?.byteLength).toBe(bin.length);
    const sizes: Record<string, number> = { SCALAR: 1, VEC2: 2, VEC3: 3 };
    const bytes: Record<number, number> = { 5126: 4, 5123: 2 };
    const quads = crossFrames(FRAMES).length;
    expect(json.accessors.map((a) => a.count)).toEqual([
      4 * quads,
      4 * quads,
      4 * quads,
      6 * quads,
    ]);
    for (const a of json.accessors) {
      const view = json.bufferViews[a.bufferView]!;
      expect(view.byteLength).toBe(a.count * sizes[a.type]! * bytes[a.componentType]!);
      expect(view.byteOffset % 4).toBe(0);
      expect(view.byteOffset + view.byteLength).toBeLessThanOrEqual(bin.length);
    }
  });

  it('embeds the atlas PNG as the base colour texture of a MASK material', () => {
    const material = json.materials[0]!;
    expect(material.alphaMode).toBe('MASK');
    const texture = json.textures[material.pbrMetallicRoughness.baseColorTexture.index]!;
    const image = json.images[texture.source]!;
    expect(image.mimeType).toBe('image/png');
    const view = json.bufferViews[image.bufferView]!;
    expect(bin.subarray(view.byteOffset, view.byteOffset + view.byteLength)).toEqual(png);
  });

  it('describes the atlas, the levels and the bounds in extras', () => {
    const node = json.nodes.find((n) => n.name === 'oak_impostor')!;
    const atlas = node.extras?.sylva_impostor as Record<string, unknown>;
    expect(atlas.frames).toBe(FRAMES);
    expect(atlas.atlas_px).toBe(SIZE);
    const directions = atlas.directions as Vec3[];
    expect(directions).toHaveLength(FRAMES * FRAMES);
    const d = frameDirection(1, 2, FRAMES);
    directions[1 * FRAMES + 2]!.forEach((v, k) => expect(v).toBeCloseTo(d[k]!, 5));
    expect(node.extras?.sylva_lod?.screen_sizes).toEqual([0.6, 0.4, 0.28]);
    expect(node.extras?.bounds).toEqual({ min: [-3, 0, -3.5], max: [4, 8, 3] });
  });

  it('each quad faces its view, spans the sphere and maps its frame', () => {
    const { positions, normals, uvs } = crossQuads(input(png));
    crossFrames(FRAMES).forEach(([i, j], q) => {
      const d = frameDirection(i, j, FRAMES);
      expect(Math.abs(d[1])).toBeLessThan(1e-6); // a horizon view
      const { right, up } = viewBasis(d);
      const [u0, v0, u1, v1] = frameUv(i, j, FRAMES);
      // Corner 2: top right of the image, at centre + (right + up) · radius.
      const o = q * 4 + 2;
      for (let a = 0; a < 3; a++) {
        const expected = input(png).centre[a]! + (right[a]! + up[a]!) * 5 + d[a]! * 0.01;
        expect(positions[o * 3 + a]).toBeCloseTo(expected, 5);
        // The view direction tilted 45° up.
        expect(normals[o * 3 + a]).toBeCloseTo((d[a]! + (a === 1 ? 1 : 0)) / Math.SQRT2, 6);
      }
      expect([uvs[o * 2], uvs[o * 2 + 1]]).toEqual([u1, v0]);
      expect([uvs[q * 8], uvs[q * 8 + 1]]).toEqual([u0, v1]);
    });
  });
});
