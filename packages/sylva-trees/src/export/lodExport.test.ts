/** The levels-of-detail export (worker handler, real core): three level GLBs and the impostor, zipped. */
import { unzipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { loadWasm } from '../testing/realWasm';
import { createHandler } from '../worker/handler';
import type { WorkerRequest, WorkerResponse } from '../worker/protocol';
import { lodFileNames } from './lodExport';

/** A small two-level tree with leaves: its levels export in well under a second. */
const SMALL = { levels: 2, l1_branches: 8, leaves: 4 };

function run(request: WorkerRequest) {
  const sent: { message: WorkerResponse; transfer: Transferable[] }[] = [];
  createHandler(loadWasm(), (message, transfer) => sent.push({ message, transfer }))(request);
  const last = sent.at(-1);
  if (last?.message.type !== 'exported') throw new Error(JSON.stringify(last?.message));
  return { message: last.message, transfer: last.transfer };
}

/** The JSON chunk of a GLB. */
function glbJson(bytes: Uint8Array | undefined): Record<string, unknown> {
  if (!bytes) throw new Error('no file');
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  expect(new TextDecoder().decode(bytes.subarray(0, 4))).toBe('glTF');
  expect(view.getUint32(8, true)).toBe(bytes.length);
  const text = new TextDecoder().decode(bytes.subarray(20, 20 + view.getUint32(12, true)));
  return JSON.parse(text) as Record<string, unknown>;
}

/** The vertex count of the mesh of the node named `name`. */
function vertices(json: Record<string, unknown>, name: string): number {
  const nodes = json.nodes as { name?: string; mesh?: number }[];
  const meshes = json.meshes as { primitives: { attributes: { POSITION: number } }[] }[];
  const accessors = json.accessors as { count: number }[];
  const node = nodes.find((n) => n.name === name && n.mesh !== undefined);
  const mesh = meshes[node?.mesh ?? -1];
  if (!mesh) throw new Error(`no mesh ${name}`);
  return mesh.primitives.reduce((n, p) => n + (accessors[p.attributes.POSITION]?.count ?? 0), 0);
}

describe('LOD export', () => {
  it('zips the three levels (falling vertex counts) and the impostor the request brings', () => {
    const impostor = new Uint8Array([1, 2, 3, 4]);
    const { message, transfer } = run({
      type: 'export',
      id: 3,
      params: SMALL,
      format: 'lods',
      name: 'oak',
      impostor,
    });
    const [zip, ...more] = message.files;
    expect(more).toEqual([]);
    if (!zip || !('bytes' in zip)) throw new Error('a ZIP comes as bytes');
    expect(zip.name).toBe('oak-lods.zip');
    expect(transfer).toEqual([zip.bytes.buffer]);
    const files = unzipSync(zip.bytes);
    expect(Object.keys(files)).toEqual(lodFileNames('oak'));
    expect(lodFileNames('oak')).toEqual([
      'oak_LOD0.glb',
      'oak_LOD1.glb',
      'oak_LOD2.glb',
      'oak_impostor.glb',
    ]);
    expect(files['oak_impostor.glb']).toEqual(impostor);
    const counts = [0, 1, 2].map((l) => {
      const json = glbJson(files[`oak_LOD${l}.glb`]);
      const nodes = json.nodes as { name?: string; extras?: { sylva_lod?: { level?: number } } }[];
      expect(nodes[0]?.name).toBe('oak');
      expect(nodes.find((n) => n.name === `oak_LOD${l}`)?.extras?.sylva_lod?.level).toBe(l);
      expect(nodes.some((n) => /_LOD/.test(n.name ?? '') && n.name !== `oak_LOD${l}`)).toBe(false);
      return vertices(json, 'bark') + vertices(json, 'leaves');
    });
    expect(counts[0]).toBeGreaterThan(counts[1]!);
    expect(counts[1]).toBeGreaterThan(counts[2]!);
    // The same tree as a plain GLB export: LOD0's hash.
    const glb = run({ type: 'export', id: 4, params: SMALL, format: 'glb' });
    expect(message.hash).toBe(glb.message.hash);
  });

  it('strict: no level lists a glTF extension; the ZIP is named -lods-strict', () => {
    const { message } = run({ type: 'export', id: 5, params: SMALL, format: 'lods', strict: true });
    const [zip] = message.files;
    if (!zip || !('bytes' in zip)) throw new Error('a ZIP comes as bytes');
    expect(zip.name).toBe('tree-lods-strict.zip');
    const files = unzipSync(zip.bytes);
    // Without an impostor in the request, the three levels only.
    expect(Object.keys(files)).toEqual(lodFileNames('tree').slice(0, 3));
    for (const bytes of Object.values(files)) {
      const json = glbJson(bytes);
      expect(json.extensionsUsed).toBeUndefined();
      expect(json.extensionsRequired).toBeUndefined();
    }
  });
});
