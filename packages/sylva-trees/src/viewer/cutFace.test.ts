/**
 * The cut faces' end grain: the worker bakes it once a tree has a cut (and again for a new bark
 * type), the `cut_face` group draws with its own material slot, and that material takes the
 * maps (clamped disc textures) and follows the wind like the bark.
 */
import { ClampToEdgeWrapping, NoColorSpace, SRGBColorSpace, type DataTexture } from 'three';
import { describe, expect, it } from 'vitest';
import type { Edit } from '../core/edits';
import type { EndGrainBuffers } from '../core/types';
import { loadWasm } from '../testing/realWasm';
import { harness } from '../testing/workerHarness';
import { END_GRAIN_TEXTURE_SIZE, endGrainOf, hasCutFaces } from '../worker/generate';
import { CUT_FACE_FLAT_COLOR, createCutFaceMaterial, EndGrainTextures } from './cutFaceMaterial';
import { MATERIAL_INDEX, buildTreeGeometry } from './geometry';
import { TreeObject } from './TreeObject';

/** A cut on a main branch of the default tree, 0.6 m out from the trunk. */
const CUT: Edit = { op: 'cut', at: [-0.19, 5.94, 0.59] };

function grain(size: number, kind = 0): EndGrainBuffers {
  const n = size * size * 4;
  return { size, kind, color: new Uint8Array(n).fill(200), normal: new Uint8Array(n).fill(128) };
}

describe('cut face material slot', () => {
  it('maps each group to its own slot: bark, leaves, cut face', () => {
    expect(MATERIAL_INDEX).toEqual({ bark: 0, leaves: 1, cut_face: 2, organ: 1 });
  });

  it('a tree with a cut has a cut_face group drawn with slot 2, on the same buffers', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: {}, edits: [CUT] });
    const tree = h.tree();
    expect(hasCutFaces(tree.meta)).toBe(true);
    const geometry = buildTreeGeometry(tree);
    const faces = geometry.groups.filter((g) => g.materialIndex === 2);
    const want = tree.meta.groups.find((g) => g.material === 'cut_face');
    expect(faces).toEqual([{ start: want?.start, count: want?.count, materialIndex: 2 }]);
    // The geometry wraps the transferred arrays (no copy on the main thread).
    expect(geometry.getAttribute('uv').array).toBe(tree.uvs);
    // The face's uvs are the disc: inside [0.5 ± 0.49].
    const idx = tree.indices.subarray(want!.start, want!.start + want!.count);
    for (const i of idx) {
      const [u, v] = [tree.uvs[2 * i]!, tree.uvs[2 * i + 1]!];
      expect(Math.hypot(u - 0.5, v - 0.5)).toBeLessThanOrEqual(0.4901);
    }
  });
});

describe('end grain from the worker', () => {
  it('is baked only once a tree has a cut, transferred, and again for a new bark type', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: {} });
    h.handle({ type: 'generate', id: 2, params: {}, edits: [CUT] });
    h.handle({ type: 'generate', id: 3, params: { seed: 0 }, edits: [CUT] });
    h.handle({ type: 'generate', id: 4, params: { bark_type: 1 }, edits: [CUT] });
    const r = h.results();
    expect(r.map((x) => x.endGrain?.kind)).toEqual([undefined, 0, undefined, 1]);
    const first = r[1]!.endGrain!;
    const n = END_GRAIN_TEXTURE_SIZE * END_GRAIN_TEXTURE_SIZE * 4;
    expect(first.size).toBe(END_GRAIN_TEXTURE_SIZE);
    expect([first.color.length, first.normal.length]).toEqual([n, n]);
    const transfer = h.sent.filter((s) => s.message.type === 'result')[1]!.transfer;
    expect(transfer).toEqual(expect.arrayContaining([first.color.buffer, first.normal.buffer]));
    expect(r[3]!.endGrain!.color).not.toEqual(first.color);
    // The merged tree keeps the latest.
    expect(h.tree().endGrain?.kind).toBe(1);
  });

  it('comes ahead of the first cut when asked for, so that the cut answers without the bake', () => {
    const wasm = loadWasm();
    const bakes: number[] = [];
    const counted = {
      ...wasm,
      end_grain_maps: (kind: number, size: number) => {
        bakes.push(kind);
        return wasm.end_grain_maps!(kind, size);
      },
    };
    const h = harness(counted);
    h.handle({ type: 'generate', id: 1, params: {} });
    // The Cut tool chosen: the same tree again, with its end grain and nothing else.
    h.handle({ type: 'generate', id: 2, params: {}, endGrain: true });
    // The first cut: no bake, no end grain in its answer (the viewer has it).
    h.handle({ type: 'generate', id: 3, params: {}, edits: [CUT] });
    const r = h.results();
    expect(r.map((x) => x.endGrain?.kind)).toEqual([undefined, 0, undefined]);
    expect(r[1]!.bark).toBeUndefined();
    expect(hasCutFaces(r[2]!.meta)).toBe(true);
    expect(bakes).toEqual([0]);
    // Asked for again: already sent for this bark type.
    h.handle({ type: 'generate', id: 4, params: {}, edits: [CUT], endGrain: true });
    expect(bakes).toEqual([0]);
    expect(h.tree().endGrain?.kind).toBe(0);
  });

  it('splits the core buffer into colour then normal, the disc opaque inside', () => {
    const wasm = loadWasm();
    const g = endGrainOf(wasm, 2)!;
    const bytes = wasm.end_grain_maps!(2, END_GRAIN_TEXTURE_SIZE);
    const same = (a: Uint8Array, b: Uint8Array) => Buffer.from(a).equals(Buffer.from(b));
    expect(same(g.color, bytes.subarray(0, g.color.length))).toBe(true);
    expect(same(g.normal, bytes.subarray(g.color.length))).toBe(true);
    const at = (x: number, y: number) => 4 * (y * g.size + x);
    const c = g.size / 2;
    expect(g.color[at(c, c) + 3]).toBe(255);
    expect(g.color[at(0, 0) + 3]).toBe(0);
    expect(endGrainOf({ ...wasm, end_grain_maps: undefined })).toBeUndefined();
  });
});

describe('cut face material', () => {
  it('takes the end grain as clamped colour (sRGB) and normal maps, and drops them again', () => {
    const material = createCutFaceMaterial();
    expect(material.map).toBeNull();
    expect(`#${material.color.getHexString()}`).toBe(CUT_FACE_FLAT_COLOR);
    const textures = new EndGrainTextures(material);
    textures.set(grain(16, 3));
    const map = material.map as DataTexture;
    const normal = material.normalMap as DataTexture;
    expect(map.colorSpace).toBe(SRGBColorSpace);
    expect(normal.colorSpace).toBe(NoColorSpace);
    for (const t of [map, normal]) {
      expect([t.wrapS, t.wrapT, t.flipY]).toEqual([
        ClampToEdgeWrapping,
        ClampToEdgeWrapping,
        false,
      ]);
    }
    expect(material.color.getHexString()).toBe('ffffff');
    expect([textures.kind, textures.size]).toEqual([3, 16]);
    // A buffer of the wrong size changes nothing.
    textures.set({ ...grain(16), normal: new Uint8Array(5) });
    expect(material.map).toBe(map);
    textures.dispose();
    expect([material.map, material.normalMap, textures.kind]).toEqual([null, null, -1]);
    expect(`#${material.color.getHexString()}`).toBe(CUT_FACE_FLAT_COLOR);
  });

  it('is the third material of the tree, with the maps and the wind', () => {
    const h = harness();
    h.handle({ type: 'generate', id: 1, params: {}, edits: [CUT] });
    const tree = new TreeObject();
    tree.setTree(h.tree());
    const materials = tree.barkMesh!.material;
    expect(materials).toHaveLength(3);
    const face = materials[MATERIAL_INDEX.cut_face]!;
    expect(face.name).toBe('cut_face');
    expect(face).not.toBe(materials[MATERIAL_INDEX.bark]);
    expect(face.map?.image).toMatchObject({ width: END_GRAIN_TEXTURE_SIZE });
    expect(face.normalMap).not.toBeNull();
    expect(tree.endGrainKind).toBe(0);
    // The wind moves the face with its branch: the same vertex patch as the bark's.
    const vertexShader = '#include <common>\nvoid main() {\n#include <begin_vertex>\n}';
    const shader = { vertexShader, fragmentShader: '', uniforms: {} };
    face.onBeforeCompile(shader as never, undefined as never);
    expect(shader.vertexShader).toContain('windPivot');
    tree.dispose();
  });
});
