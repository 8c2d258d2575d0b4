/** Mesh export, worker side (the real core's exporters), the client, and the ZIP writer. */
import { unzipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { loadWasm } from '../testing/realWasm';
import { harness } from '../testing/workerHarness';
import type { WasmApi } from '../core/types';
import { createHandler } from '../worker/handler';
import type { WorkerResponse } from '../worker/protocol';
import { ExportClient } from './exportClient';
import {
  blobPart,
  exportFiles,
  exportFormatsOf,
  fileStem,
  type CoreFile,
  type ExportableTree,
} from './exportHandler';
import { zipFiles } from './zip';

/**
 * A member of a wasm object, methods bound to the object itself: called through the proxy,
 * `free()` would unregister the proxy from wasm-bindgen's finalizer instead of the tree, and the
 * finalizer would later free the tree a second time (a "memory access out of bounds" in a later
 * test).
 */
function member(target: object, key: string | symbol): unknown {
  const value: unknown = Reflect.get(target, key);
  return typeof value === 'function' ? (value as (...a: unknown[]) => unknown).bind(target) : value;
}

/** The real wasm whose trees hide the exporters (a core from before the export branch). */
function withoutExporters(): WasmApi {
  const real = loadWasm();
  const hidden = new Set([
    'to_glb_file',
    'to_glb',
    'to_obj',
    'to_mtl',
    'obj_texture',
    'obj_texture_names',
  ]);
  return {
    ...real,
    generate: (json: string) =>
      new Proxy(real.generate(json), {
        get: (tree, key): unknown => (hidden.has(String(key)) ? undefined : member(tree, key)),
      }),
  };
}

/** The real wasm whose trees lack `to_glb_file` (a core from before it). */
function withoutFileExport(): WasmApi {
  const real = loadWasm();
  return {
    ...real,
    generate: (json: string) =>
      new Proxy(real.generate(json), {
        get: (tree, key): unknown => (key === 'to_glb_file' ? undefined : member(tree, key)),
      }),
  };
}

/** A small two-level tree: its GLB exports in well under a second. */
const SMALL = { levels: 2, l1_branches: 8, leaves: 4 };

function collect(wasm: WasmApi) {
  const sent: { message: WorkerResponse; transfer: Transferable[] }[] = [];
  const handle = createHandler(wasm, (message, transfer) => sent.push({ message, transfer }));
  return { sent, handle };
}

function exported(sent: { message: WorkerResponse }[]) {
  const message = sent.at(-1)?.message;
  if (message?.type !== 'exported') throw new Error(JSON.stringify(message));
  return message;
}

/** The JSON chunk of a GLB. */
function glbJson(bytes: Uint8Array): Record<string, unknown> {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const text = new TextDecoder().decode(bytes.subarray(20, 20 + view.getUint32(12, true)));
  return JSON.parse(text) as Record<string, unknown>;
}

describe('blobPart', () => {
  it('copies a view of a shared memory (the threaded core), and only then', () => {
    const shared = new Uint8Array(new SharedArrayBuffer(16)).map((_, i) => i);
    const view = new Uint8Array(shared.buffer, 4, 8);
    const part = blobPart(view);
    expect(part.buffer).toBeInstanceOf(ArrayBuffer);
    expect([...part]).toEqual([4, 5, 6, 7, 8, 9, 10, 11]);
    const plain = new Uint8Array(8);
    expect(blobPart(plain)).toBe(plain);
  });
});

describe('export feature check', () => {
  it('lists only the exporters the GeneratedTree class has', () => {
    expect(exportFormatsOf({})).toEqual([]);
    expect(exportFormatsOf({ GeneratedTree: { prototype: { to_glb() {} } } })).toEqual(['glb']);
    expect(exportFormatsOf(loadWasm())).toEqual(['glb', 'obj', 'glb-growth', 'glb-years', 'lods']);
  });

  it('file stems are plain names', () => {
    expect(fileStem('sylva-quaking_aspen-seed7')).toBe('sylva-quaking_aspen-seed7');
    expect(fileStem('../../etc/passwd')).toBe('etc-passwd');
    expect(fileStem('')).toBe('tree');
    expect(fileStem(undefined)).toBe('tree');
  });
});

describe('export request (worker handler, real core)', () => {
  it('GLB: regenerates the params, glTF 2.0 binary, a Blob read from the core memory', async () => {
    const h = harness();
    const { sent, handle } = h;
    handle({ type: 'generate', id: 1, params: { seed: 3, levels: 2 } });
    const shown = h.tree();
    handle({
      type: 'export',
      id: 4,
      params: { seed: 3, levels: 2 },
      format: 'glb',
      leaves: 'baked',
      name: 'oak-1',
    });
    const message = exported(sent);
    expect(message.id).toBe(4);
    // The same tree as the viewer shows.
    expect(shown.meta.hash).toBe(message.hash);
    const [file] = message.files;
    expect(file?.name).toBe('oak-1.glb');
    expect(file?.mime).toBe('model/gltf-binary');
    if (!file || !('blob' in file)) throw new Error('a GLB comes as a Blob');
    expect(file.blob.type).toBe('model/gltf-binary');
    const bytes = new Uint8Array(await file.blob.arrayBuffer());
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    expect(new TextDecoder().decode(bytes.subarray(0, 4))).toBe('glTF');
    expect(view.getUint32(4, true)).toBe(2);
    expect(view.getUint32(8, true)).toBe(bytes.length);
    expect(sent.at(-1)?.transfer).toEqual([]);
    // The same bytes as the copying exporter.
    const tree = loadWasm().generate(JSON.stringify({ seed: 3, levels: 2 })) as ExportableTree;
    expect(bytes).toEqual(tree.to_glb?.(JSON.stringify({ leaves: 'baked' })));
    tree.free();
  });

  it("strict GLB: the core's strict option, no glTF extension listed, named STEM-strict.glb", async () => {
    const { sent, handle } = harness();
    handle({ type: 'export', id: 6, params: SMALL, format: 'glb', strict: true, name: 'oak' });
    const [file] = exported(sent).files;
    if (!file || !('blob' in file)) throw new Error('a GLB comes as a Blob');
    expect(file.name).toBe('oak-strict.glb');
    const bytes = new Uint8Array(await file.blob.arrayBuffer());
    expect(glbJson(bytes).extensionsUsed).toBeUndefined();
    expect(glbJson(bytes).extensionsRequired).toBeUndefined();
    const tree = loadWasm().generate(JSON.stringify(SMALL)) as ExportableTree;
    const copy = tree.to_glb?.(JSON.stringify({ strict: true }));
    // Compared as buffers: a deep equality of megabytes is slow.
    expect(copy && Buffer.compare(bytes, copy)).toBe(0);
    // The default file of the same tree requires quantization.
    expect(glbJson(tree.to_glb?.('{}') ?? bytes).extensionsRequired).toEqual([
      'KHR_mesh_quantization',
    ]);
    tree.free();
  });

  it("growth GLB: the core's growth animation from year 0 to the Age, leaves baked", async () => {
    const { sent, handle } = harness();
    const params = { ...SMALL, age: 12, maturity: 30 };
    handle({ type: 'export', id: 7, params, format: 'glb-growth', name: 'oak' });
    const [file] = exported(sent).files;
    if (!file || !('blob' in file)) throw new Error('a GLB comes as a Blob');
    expect(file.name).toBe('oak-growth.glb');
    const bytes = new Uint8Array(await file.blob.arrayBuffer());
    const json = glbJson(bytes) as {
      animations: { samplers: { input: number }[]; channels: unknown[] }[];
      accessors: { max?: number[] }[];
      nodes: { name: string; extensions?: unknown }[];
    };
    expect(json.animations).toHaveLength(1);
    const input = json.animations[0]?.samplers[0]?.input ?? -1;
    expect(json.accessors[input]?.max).toEqual([12]);
    expect(json.animations[0]?.channels).toHaveLength(2);
    expect(json.nodes.find((n) => n.name === 'leaves')?.extensions).toBeUndefined();
    const tree = loadWasm().generate(JSON.stringify(params)) as ExportableTree & {
      to_growth_glb_file(o: string, age: number, maturity: number): CoreFile;
    };
    const core = tree.to_growth_glb_file(JSON.stringify({ leaves: 'baked' }), 12, 30);
    const copy = new Uint8Array(core.memory().buffer, core.ptr(), core.byte_length()).slice();
    core.free();
    tree.free();
    expect(Buffer.compare(bytes, copy)).toBe(0);
  });

  it('growth years: a zip of one GLB per whole year, each the tree at that Age', () => {
    const { sent, handle } = collect(loadWasm());
    const params = { ...SMALL, age: 3 };
    handle({ type: 'export', id: 8, params, format: 'glb-years', name: 'oak' });
    const [zip] = exported(sent).files;
    if (!zip || !('bytes' in zip)) throw new Error('a ZIP comes as bytes');
    expect(zip.name).toBe('oak-years.zip');
    const files = unzipSync(zip.bytes);
    expect(Object.keys(files)).toEqual(['year_001.glb', 'year_002.glb', 'year_003.glb']);
    for (const age of [1, 2, 3]) {
      const tree = loadWasm().generate(JSON.stringify({ ...params, age })) as ExportableTree;
      const glb = tree.to_glb?.(JSON.stringify({ leaves: 'baked' }));
      tree.free();
      const name = `year_00${age}.glb`;
      expect(glb && Buffer.compare(files[name] ?? new Uint8Array(0), glb)).toBe(0);
    }
  });

  it('GLB from a core with only the copying exporter: bytes transferred', () => {
    const { sent, handle } = collect(withoutFileExport());
    handle({ type: 'export', id: 5, params: SMALL, format: 'glb' });
    const [file] = exported(sent).files;
    if (!file || !('bytes' in file)) throw new Error('bytes expected');
    expect(new TextDecoder().decode(file.bytes.subarray(0, 4))).toBe('glTF');
    expect(sent.at(-1)?.transfer).toEqual([file.bytes.buffer]);
  });

  it('OBJ: one deflated ZIP of the OBJ, its MTL and the textures the MTL names', () => {
    const { sent, handle } = collect(loadWasm());
    handle({ type: 'export', id: 1, params: { levels: 2 }, format: 'obj', name: 'fir' });
    const [zip, ...more] = exported(sent).files;
    expect(more).toEqual([]);
    if (!zip || !('bytes' in zip)) throw new Error('a ZIP comes as bytes');
    expect(zip.name).toBe('fir-obj.zip');
    expect(zip.mime).toBe('application/zip');
    expect(sent.at(-1)?.transfer).toEqual([zip.bytes.buffer]);
    const files = unzipSync(zip.bytes);
    const names = Object.keys(files);
    expect(names.slice(0, 2)).toEqual(['fir.obj', 'fir.mtl']);
    const obj = new TextDecoder().decode(files['fir.obj']);
    const mtl = new TextDecoder().decode(files['fir.mtl']);
    expect(obj).toMatch(/^mtllib fir\.mtl$/m);
    expect(obj).toMatch(/^v -?\d/m);
    expect(mtl).toMatch(/^newmtl /m);
    expect(names.length).toBeGreaterThan(2);
    for (const texture of names.slice(2)) {
      expect(mtl).toContain(texture);
      expect([...(files[texture] ?? new Uint8Array(0)).subarray(0, 4)]).toEqual([
        0x89, 0x50, 0x4e, 0x47,
      ]);
    }
    // The same files as the core's exporters write, compressed.
    const tree = loadWasm().generate(JSON.stringify({ levels: 2 })) as ExportableTree;
    const loose = exportFiles(tree, 'obj', undefined, 'fir');
    tree.free();
    expect(names).toEqual(loose.map((f) => f.name));
    for (const file of loose) {
      expect(files[file.name]).toEqual('bytes' in file ? file.bytes : null);
    }
    const stored = loose.reduce((n, f) => n + ('bytes' in f ? f.bytes.length : 0), 0);
    expect(zip.bytes.length).toBeLessThan(stored / 2);
    // The default two-level tree's OBJ (about 45 MB before compression) takes a while.
  }, 120_000);

  it('a core without exporters, or invalid params, answer a typed error', () => {
    const { sent, handle } = collect(withoutExporters());
    handle({ type: 'export', id: 2, params: { levels: 99 }, format: 'glb' });
    handle({ type: 'export', id: 3, params: {}, format: 'glb' });
    handle({ type: 'export', id: 4, params: {}, format: 'obj' });
    const errors = sent.map((s) => (s.message.type === 'error' ? s.message.error : null));
    expect(errors[0]?.param).toBe('levels');
    expect(errors[1]?.message).toMatch(/no GLB exporter/);
    expect(errors[2]?.message).toMatch(/no OBJ exporter/);
  });
});

describe('ExportClient', () => {
  it('reports the formats from ready and resolves exports through the handler', async () => {
    const wasm = loadWasm();
    let stopped = 0;
    const client = new ExportClient((onMessage) => {
      const handle = createHandler(wasm, (message) => queueMicrotask(() => onMessage(message)));
      queueMicrotask(() =>
        onMessage({
          type: 'ready',
          registry: [],
          presets: [],
          version: 'test',
          exportFormats: exportFormatsOf(wasm),
        }),
      );
      return {
        post: (request) => queueMicrotask(() => handle(request)),
        terminate: () => stopped++,
      };
    });
    expect(await client.formats()).toEqual(['glb', 'obj', 'glb-growth', 'glb-years', 'lods']);
    const response = await client.export({ seed: 2 }, [], 'glb');
    const [glb] = response.files;
    const bytes = glb && 'blob' in glb ? new Uint8Array(await glb.blob.arrayBuffer()) : null;
    expect(new TextDecoder().decode(bytes?.subarray(0, 4))).toBe('glTF');
    await expect(client.export({ levels: 99 }, [], 'obj')).rejects.toThrow(/levels/i);
    client.dispose();
    expect(stopped).toBe(1);
  });

  it('refuses a format the core lacks', async () => {
    const client = new ExportClient((onMessage) => {
      queueMicrotask(() =>
        onMessage({ type: 'ready', registry: [], presets: [], version: 't', exportFormats: [] }),
      );
      return { post: () => undefined, terminate: () => undefined };
    });
    await expect(client.export({}, [], 'glb')).rejects.toThrow(/cannot export GLB/);
  });
});

describe('zipFiles', () => {
  const enc = new TextEncoder();
  const obj = enc.encode('mtllib tree.mtl\n' + 'v 0.125 1.5 -0.25 0.8 0.7 0.6\n'.repeat(4000));
  const mtl = enc.encode('newmtl bark\nKd 1 1 1\n');
  // A PNG-like file: bytes that do not compress (already deflated), stored as they are.
  const png = new Uint8Array(4096).map((_, i) => (i * 2654435761) >>> 24);
  const files = [
    { name: 'tree.obj', bytes: obj },
    { name: 'tree.mtl', bytes: mtl },
    { name: 'tree_bark_color.png', bytes: png },
  ];

  it('fflate unzips the archive back to the same files, in order', () => {
    const back = unzipSync(zipFiles(files));
    expect(Object.keys(back)).toEqual(['tree.obj', 'tree.mtl', 'tree_bark_color.png']);
    for (const f of files) expect(back[f.name]).toEqual(f.bytes);
  });

  it('deflates text (smaller than a stored archive), stores PNGs, same bytes every time', () => {
    const zip = zipFiles(files);
    const stored = files.reduce((n, f) => n + 30 + 46 + 2 * f.name.length + f.bytes.length, 22);
    expect(zip.length).toBeLessThan(stored / 10);
    // Local headers: method 8 (deflate) for the OBJ, 0 (stored) for the PNG, 1980-01-01.
    const view = new DataView(zip.buffer, zip.byteOffset, zip.byteLength);
    expect(view.getUint32(0, true)).toBe(0x04034b50);
    expect(view.getUint16(8, true)).toBe(8);
    expect(view.getUint16(12, true)).toBe(0x21);
    const end = zip.length - 22;
    const central = view.getUint32(end + 16, true);
    const thirdCentral = central + 2 * 46 + 'tree.obj'.length + 'tree.mtl'.length;
    expect(view.getUint16(thirdCentral + 10, true)).toBe(0);
    expect(view.getUint32(thirdCentral + 20, true)).toBe(png.length);
    expect(zipFiles(files)).toEqual(zip);
  });

  it('refuses two files of one name', () => {
    expect(() => zipFiles([files[1], files[1]].flatMap((f) => (f ? [f] : [])))).toThrow(
      /Two files named "tree.mtl"/,
    );
  });
});
