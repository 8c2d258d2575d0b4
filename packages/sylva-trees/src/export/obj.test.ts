/**
 * The core's exporters through the real wasm build: the OBJ re-parsed by three.js's OBJLoader
 * has exactly the tree's triangles (bark plus every leaf baked), the MTL names the textures the
 * binding hands out as PNGs, and the GLB starts with a well-formed header.
 */
import { describe, expect, it } from 'vitest';
import { InstancedMesh, Mesh, type BufferGeometry, type Object3D } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { loadWasm, realPresets } from '../testing/realWasm';
import type { WasmTree } from '../core/types';

interface Exporting extends WasmTree {
  wind(): Float32Array;
  to_glb(optionsJson: string): Uint8Array;
  to_obj(name: string, optionsJson: string): string;
  to_mtl(name: string, optionsJson: string): string;
  obj_texture_names(name: string, optionsJson: string): string[];
  obj_texture(optionsJson: string, index: number): Uint8Array;
}

function generate(values: Record<string, number>): Exporting {
  return loadWasm().generate(JSON.stringify(values)) as Exporting;
}

function triangles(root: Object3D): number {
  let n = 0;
  root.traverse((o) => {
    if (o instanceof Mesh) {
      const g = (o as Mesh<BufferGeometry>).geometry;
      n += (g.index ? g.index.count : (g.getAttribute('position')?.count ?? 0)) / 3;
    }
  });
  return n;
}

/** Bark triangles plus the leaf mesh's triangles once per leaf. */
function expectedTriangles(tree: Exporting): number {
  const meta = JSON.parse(tree.meta_json()) as { triangles: number; leaves: number };
  const leafTriangles = (tree.leaf_indices?.().length ?? 0) / 3;
  return meta.triangles + leafTriangles * meta.leaves;
}

describe('OBJ export', () => {
  const small = realPresets().filter((p) => ['default', 'fir', 'grown_bushy'].includes(p.name));

  it.each(small.map((p) => [p.name, p.values] as const))(
    '%s: OBJLoader reads back the same triangle count',
    (_name, values) => {
      const tree = generate(values);
      try {
        const expected = expectedTriangles(tree);
        const parsed = new OBJLoader().parse(tree.to_obj('tree', ''));
        expect(triangles(parsed)).toBe(expected);
        const names = parsed.children.map((c) => c.name);
        expect(names).toContain('bark');
      } finally {
        tree.free();
      }
    },
    120_000,
  );

  it('leaves none: bark only', () => {
    const tree = generate({ growth_mode: 1 });
    try {
      const bare = new OBJLoader().parse(tree.to_obj('tree', '{"leaves":"none"}'));
      const meta = JSON.parse(tree.meta_json()) as { triangles: number };
      expect(triangles(bare)).toBe(meta.triangles);
      expect(bare.children.map((c) => c.name)).toEqual(['bark']);
    } finally {
      tree.free();
    }
  });

  it('the MTL names the PNG textures the binding returns', () => {
    const tree = generate({});
    try {
      const obj = tree.to_obj('oak', '');
      expect(obj).toContain('mtllib oak.mtl');
      const mtl = tree.to_mtl('oak', '');
      const names = tree.obj_texture_names('oak', '');
      expect(names).toEqual([
        'oak_bark_color.png',
        'oak_bark_normal.png',
        'oak_leaf_color.png',
        'oak_leaf_normal.png',
      ]);
      names.forEach((name, i) => {
        expect(mtl).toContain(name);
        const png = tree.obj_texture('', i);
        expect(Array.from(png.slice(0, 8))).toEqual([
          0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a,
        ]);
      });
      expect(tree.obj_texture_names('oak', '{"textures":false}')).toEqual([]);
      expect(tree.to_mtl('oak', '{"textures":false}')).not.toContain('map_Kd');
    } finally {
      tree.free();
    }
  });
});

describe('GLB export', () => {
  it('writes a GLB header and JSON chunk; bad options throw a SylvaError', () => {
    const tree = generate({});
    try {
      const glb = tree.to_glb('{"leaves":"baked"}');
      const view = new DataView(glb.buffer, glb.byteOffset, glb.byteLength);
      expect(new TextDecoder().decode(glb.slice(0, 4))).toBe('glTF');
      expect(view.getUint32(4, true)).toBe(2);
      expect(view.getUint32(8, true)).toBe(glb.byteLength);
      const jsonLength = view.getUint32(12, true);
      const json = JSON.parse(new TextDecoder().decode(glb.slice(20, 20 + jsonLength))) as {
        asset: { generator: string };
        nodes: { name: string }[];
      };
      expect(json.asset.generator).toMatch(/^Sylva /);
      expect(json.nodes.map((n) => n.name)).toEqual(['sylva_tree', 'bark', 'leaves']);
      expect(() => tree.to_glb('{"leaves":"sideways"}')).toThrow(/"kind":"input"/);
    } finally {
      tree.free();
    }
  });

  it("three.js's GLTFLoader reads the baked leaves: one mesh, a tint and a twig's wind per vertex", async () => {
    const tree = generate({});
    try {
      const meta = JSON.parse(tree.meta_json()) as { leaves: number };
      const leafVertices = (tree.leaf_positions?.().length ?? 0) / 3;
      const glb = tree.to_glb('{"textures":false,"leaves":"baked"}');
      const buffer = glb.buffer.slice(
        glb.byteOffset,
        glb.byteOffset + glb.byteLength,
      ) as ArrayBuffer;
      const gltf = await new GLTFLoader().parseAsync(buffer, '');
      const meshes: Mesh[] = [];
      gltf.scene.traverse((o) => {
        if (o instanceof Mesh) meshes.push(o as Mesh);
      });
      expect(meshes.map((m) => m.name).sort()).toEqual(['bark', 'leaves']);
      const leaves = meshes.find((m) => m.name === 'leaves') as Mesh<BufferGeometry>;
      expect(leaves).not.toBeInstanceOf(InstancedMesh);
      const count = leafVertices * meta.leaves;
      expect(count).toBeGreaterThan(65_535);
      expect(leaves.geometry.getAttribute('position').count).toBe(count);
      expect(leaves.geometry.index?.array).toBeInstanceOf(Uint32Array);
      for (const name of ['color', '_wind_pivot', '_wind_params']) {
        expect(leaves.geometry.getAttribute(name).count).toBe(count);
      }
      // The wind is coded as the bark's (same offsets and scales).
      const bark = meshes.find((m) => m.name === 'bark') as Mesh;
      expect(leaves.userData.wind_attributes).toEqual(bark.userData.wind_attributes);
    } finally {
      tree.free();
    }
  });

  it("three.js's GLTFLoader reads the instanced leaves (textures off: no image decoding in Node)", async () => {
    const tree = generate({});
    try {
      const meta = JSON.parse(tree.meta_json()) as { leaves: number; triangles: number };
      const glb = tree.to_glb('{"textures":false}');
      const buffer = glb.buffer.slice(
        glb.byteOffset,
        glb.byteOffset + glb.byteLength,
      ) as ArrayBuffer;
      const gltf = await new GLTFLoader().parseAsync(buffer, '');
      const meshes: Mesh[] = [];
      gltf.scene.traverse((o) => {
        if (o instanceof Mesh) meshes.push(o as Mesh);
      });
      const leaves = meshes.find((m) => m.name === 'leaves');
      expect(leaves).toBeInstanceOf(InstancedMesh);
      expect((leaves as InstancedMesh).count).toBe(meta.leaves);
      expect((leaves as InstancedMesh).instanceColor).not.toBeNull();
      const bark = meshes.find((m) => m.name === 'bark') as Mesh<BufferGeometry>;
      expect(bark.geometry.getAttribute('color')).toBeDefined();
      // KHR_mesh_quantization: normals arrive as normalised bytes, read back as unit vectors.
      const normal = bark.geometry.getAttribute('normal');
      expect(normal.array).toBeInstanceOf(Int8Array);
      expect(normal.normalized).toBe(true);
      expect(Math.hypot(normal.getX(7), normal.getY(7), normal.getZ(7))).toBeCloseTo(1, 2);
      expect((bark.geometry.index?.count ?? 0) / 3).toBe(meta.triangles);
      // Wind: normalised u16 attributes; offset + scale · value (from the mesh's extras, which
      // three.js puts in userData) gives back the core's wind data within half a step.
      const wind = tree.wind();
      const doc = bark.userData.wind_attributes as Record<
        string,
        { offset: number[]; scale: number[] }
      >;
      for (const [name, key, first] of [
        ['_wind_pivot', '_WIND_PIVOT', 0],
        ['_wind_params', '_WIND_PARAMS', 4],
      ] as const) {
        const attr = bark.geometry.getAttribute(name);
        expect(attr.array).toBeInstanceOf(Uint16Array);
        expect(attr.normalized).toBe(true);
        const { offset, scale } = doc[key] ?? { offset: [], scale: [] };
        for (const v of [0, 7, 1000, attr.count - 1]) {
          for (let k = 0; k < 4; k++) {
            const decoded = (offset[k] ?? 0) + (scale[k] ?? 0) * attr.getComponent(v, k);
            const step = (scale[k] ?? 0) / 65535;
            expect(Math.abs(decoded - (wind[8 * v + first + k] ?? 0))).toBeLessThanOrEqual(
              step / 2 + 1e-5,
            );
          }
        }
      }
    } finally {
      tree.free();
    }
  });
});
