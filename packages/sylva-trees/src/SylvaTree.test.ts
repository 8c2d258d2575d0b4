// The package's API on Node with the real wasm, generated in process (`worker: false`).
import type { BufferGeometry } from 'three';
import { Texture } from 'three';
import { describe, expect, it } from 'vitest';
import { SylvaTree, SylvaTreeError, params, presets, type SylvaPresetId } from './index';

/** Geometries and textures alive under `tree.object` (disposed ones fire `dispose`). */
function resources(tree: SylvaTree): { geometries: Set<BufferGeometry>; textures: Set<Texture> } {
  const geometries = new Set<BufferGeometry>();
  const textures = new Set<Texture>();
  tree.object.traverse((node) => {
    const mesh = node as { geometry?: BufferGeometry; material?: unknown };
    if (mesh.geometry) geometries.add(mesh.geometry);
    const materials = Array.isArray(mesh.material) ? mesh.material : [mesh.material];
    for (const material of materials) {
      for (const value of Object.values((material ?? {}) as Record<string, unknown>)) {
        if (value instanceof Texture) textures.add(value as Texture);
      }
    }
  });
  return { geometries, textures };
}

describe('sylva-trees', () => {
  it('lists the presets and the registry', () => {
    expect(presets).toContain('quaking_aspen');
    const length = params.find((p) => p.id === 'l1_length');
    expect(length).toMatchObject({ label: 'Length', type: 'float', range: [0, 2] });
    expect(typeof length?.description).toBe('string');
  });

  it('creates a tree with stats, and set() regenerates it with a new hash', async () => {
    const tree = await SylvaTree.create({ preset: 'quaking_aspen', seed: 7, worker: false });
    const first = tree.stats;
    expect(first.vertices).toBeGreaterThan(1000);
    expect(first.triangles).toBeGreaterThan(1000);
    expect(first.leaves).toBeGreaterThan(100);
    expect(first.hash).toMatch(/^[0-9a-f]{16}$/);
    expect(tree.object.children.length).toBeGreaterThanOrEqual(2);
    await tree.set({ seed: 8 });
    expect(tree.stats.hash).not.toBe(first.hash);
    expect(tree.params.seed).toBe(8);
    // Latest call wins: both settle, the tree shows the last one.
    const [a, b] = [tree.set({ seed: 9 }), tree.set({ seed: 7 })];
    await Promise.all([a, b]);
    expect(tree.stats.hash).toBe(first.hash);
    tree.dispose();
  });

  it('set({ age }) grows the tree through its years; its Mature Age gives the preset tree', async () => {
    const tree = await SylvaTree.create({ preset: 'oak', worker: false });
    const mature = tree.stats;
    expect(tree.params.age).toBe(100);
    await tree.set({ age: 20 });
    expect(tree.stats.vertices).toBeLessThan(mature.vertices / 2);
    expect(tree.stats.leaves).toBeLessThan(mature.leaves);
    await tree.set({ age: 100 });
    expect(tree.stats.hash).toBe(mature.hash);
    await expect(tree.set({ age: 0 })).rejects.toMatchObject({
      kind: 'invalid_param',
      param: 'age',
    });
    tree.dispose();
  });

  it('rejects invalid parameters with the core message and keeps the tree', async () => {
    await expect(SylvaTree.create({ params: { l1_length: 3 }, worker: false })).rejects.toThrow(
      'l1_length (Length) is 3: allowed range is 0 to 2',
    );
    const tree = await SylvaTree.create({ worker: false });
    const hash = tree.stats.hash;
    const failed = tree.set({ l1_length: 3 });
    await expect(failed).rejects.toBeInstanceOf(SylvaTreeError);
    await expect(failed).rejects.toMatchObject({ kind: 'invalid_param', param: 'l1_length' });
    expect(tree.stats.hash).toBe(hash);
    await tree.set({ levels: 2 });
    expect(tree.params.l1_length).not.toBe(3);
    // A JavaScript caller (no types) may pass any name.
    const unknown = 'no_such_tree' as SylvaPresetId;
    await expect(SylvaTree.create({ preset: unknown, worker: false })).rejects.toThrow(
      /unknown preset "no_such_tree"/,
    );
    tree.dispose();
  });

  it('checks hand edits like the core and keeps the tree when they are bad', async () => {
    const bad = [
      {
        op: 'paint' as const,
        points: [[1, 5, 0]] as [number, number, number][],
        radius: 0,
        density: 400,
        segment: 0.25,
        kill: 0.4,
      },
    ];
    await expect(SylvaTree.create({ edits: bad, worker: false })).rejects.toMatchObject({
      kind: 'invalid_param',
      param: 'edits[0].radius',
      message: 'edits[0].radius is 0: allowed range is 0.02 to 10 m',
    });
    const tree = await SylvaTree.create({ worker: false, edits: [] });
    const hash = tree.stats.hash;
    await expect(tree.set({ edits: [{ op: 'cut', at: [1, 0, 0] }] })).rejects.toThrow(
      /edits\[0\]\.at is on the ground/,
    );
    expect(tree.edits).toEqual([]);
    // No edits: the same request as before edits existed, the same tree.
    await tree.set({ edits: [], seed: tree.params.seed });
    expect(tree.stats.hash).toBe(hash);
    tree.dispose();
  });

  it('reads a share link as the app does', async () => {
    const tree = await SylvaTree.fromShareLink('https://x.org/?v=1&seed=7&levels=2&nope=1', {
      worker: false,
    });
    expect(tree.params.seed).toBe(7);
    expect(tree.params.levels).toBe(2);
    const direct = await SylvaTree.create({ seed: 7, params: { levels: 2 }, worker: false });
    expect(tree.stats.hash).toBe(direct.stats.hash);
    tree.dispose();
    direct.dispose();
  });

  it('exports the GLB of the tree shown', async () => {
    const tree = await SylvaTree.create({ params: { levels: 2 }, worker: false });
    const glb = await tree.toGLB();
    expect(new TextDecoder().decode(glb.subarray(0, 4))).toBe('glTF');
    tree.dispose();
  });

  it('dispose() frees every geometry and texture and leaves the scene', async () => {
    const tree = await SylvaTree.create({ worker: false });
    const { geometries, textures } = resources(tree);
    expect(geometries.size).toBeGreaterThanOrEqual(2);
    expect(textures.size).toBeGreaterThanOrEqual(1);
    const freed = new Set<object>();
    for (const g of geometries) g.addEventListener('dispose', () => freed.add(g));
    for (const t of textures) t.addEventListener('dispose', () => freed.add(t));
    tree.dispose();
    expect(freed.size).toBe(geometries.size + textures.size);
    expect(tree.object.children).toHaveLength(0);
    await expect(tree.set({ seed: 2 })).rejects.toThrow(/disposed/);
  });
});
