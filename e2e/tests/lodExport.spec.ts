/**
 * Export → "LODs + impostor": the download is a ZIP of four GLBs (LOD0, LOD1, LOD2 and the
 * impostor made from the page's atlas), each valid for the Khronos glTF Validator, the levels'
 * drawn vertex counts falling, the impostor with its atlas as an embedded PNG texture that shows
 * the tree in the frames its crossed quads map.
 */
import { expect, test, type Page } from '@playwright/test';
import { unzipSync } from 'fflate';
import { validateBytes } from 'gltf-validator';
import { readFileSync } from 'node:fs';
import { waitForTree, watchErrors } from './helpers';

interface Gltf {
  extensionsRequired?: string[];
  accessors: { count: number }[];
  bufferViews: { byteOffset?: number; byteLength: number }[];
  images?: { bufferView: number; mimeType: string }[];
  textures?: { source: number }[];
  materials?: { pbrMetallicRoughness?: { baseColorTexture?: { index: number } } }[];
  meshes: { primitives: { attributes: Record<string, number> }[] }[];
  nodes: {
    name?: string;
    mesh?: number;
    extensions?: { EXT_mesh_gpu_instancing?: { attributes: { TRANSLATION: number } } };
    extras?: Record<string, Record<string, unknown>>;
  }[];
}

/** The JSON and BIN chunks of a GLB. */
function parse(glb: Uint8Array): { json: Gltf; bin: Uint8Array } {
  const view = new DataView(glb.buffer, glb.byteOffset, glb.byteLength);
  expect(view.getUint32(0, true)).toBe(0x46546c67);
  const length = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(glb.subarray(20, 20 + length))) as Gltf;
  return { json, bin: glb.subarray(28 + length) };
}

/** Vertices drawn: every mesh node's vertices, times its instance count when instanced. */
function drawnVertices({ json }: { json: Gltf }): number {
  let total = 0;
  for (const node of json.nodes) {
    if (node.mesh === undefined) continue;
    const mesh = json.meshes[node.mesh]!;
    const vertices = mesh.primitives.reduce(
      (n, p) => n + json.accessors[p.attributes.POSITION!]!.count,
      0,
    );
    const instancing = node.extensions?.EXT_mesh_gpu_instancing;
    total += vertices * (instancing ? json.accessors[instancing.attributes.TRANSLATION]!.count : 1);
  }
  return total;
}

/** Share of texels with alpha ≥ 128 in frame (i, j) of the atlas PNG (decoded in the page). */
async function frameCover(
  page: Page,
  png: Uint8Array,
  frames: number,
  cells: [number, number][],
): Promise<number[]> {
  return page.evaluate(
    async ({ base64, frames, cells }) => {
      const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
      const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }), {
        premultiplyAlpha: 'none',
      });
      const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
      const context = canvas.getContext('2d')!;
      context.drawImage(bitmap, 0, 0);
      const { data, width } = context.getImageData(0, 0, bitmap.width, bitmap.height);
      const cell = width / frames;
      return cells.map(([i, j]) => {
        // Frame (i, j): column i, row j from the bottom of the image.
        let on = 0;
        for (let y = (frames - 1 - j) * cell; y < (frames - j) * cell; y++) {
          for (let x = i * cell; x < (i + 1) * cell; x++)
            if (data[(y * width + x) * 4 + 3]! >= 128) on++;
        }
        return on / (cell * cell);
      });
    },
    { base64: Buffer.from(png).toString('base64'), frames, cells },
  );
}

test('Export LODs: a ZIP of four valid GLBs, levels falling, the impostor textured', async ({
  page,
}) => {
  test.setTimeout(300_000);
  const errors = watchErrors(page);
  await page.goto('/');
  await waitForTree(page);
  await page.getByTestId('export-menu').click();
  const item = page.getByTestId('export-lods');
  await expect(item).toContainText('LODs + impostor');
  await expect(item).toBeEnabled();
  await expect(page.getByTestId('export-lods-strict')).toBeEnabled();
  const downloaded = page.waitForEvent('download', { timeout: 240_000 });
  await item.click();
  const download = await downloaded;
  expect(download.suggestedFilename()).toMatch(/^sylva-.*-lods\.zip$/);
  await download.saveAs(test.info().outputPath('lods.zip'));
  const files = unzipSync(readFileSync(test.info().outputPath('lods.zip')));
  const names = Object.keys(files);
  const stem = download.suggestedFilename().replace(/-lods\.zip$/, '');
  expect(names).toEqual([0, 1, 2].map((l) => `${stem}_LOD${l}.glb`).concat(`${stem}_impostor.glb`));
  await expect(page.getByTestId('toolbar-status')).toContainText(
    'LOD0, LOD1, LOD2 and the impostor',
  );

  const sizes: string[] = [];
  for (const name of names) {
    const bytes = files[name]!;
    sizes.push(`${name}: ${(bytes.length / 1e6).toFixed(2)} MB`);
    const report = await validateBytes(bytes, { maxIssues: 100 });
    const serious = report.issues.messages.filter((m) => m.severity <= 1);
    expect(serious, `${name}: ${JSON.stringify(serious)}`).toEqual([]);
    expect(report.issues.numErrors).toBe(0);
    expect(report.issues.numWarnings).toBe(0);
    // The impostor: not even an info (its atlas side a power of two, nothing unused).
    if (name.endsWith('_impostor.glb')) expect(report.issues.messages).toEqual([]);
  }
  test.info().annotations.push({ type: 'sizes', description: sizes.join(', ') });

  const levels = names.slice(0, 3).map((n) => parse(files[n]!));
  const vertices = levels.map(drawnVertices);
  expect(vertices[0]).toBeGreaterThan(vertices[1]!);
  expect(vertices[1]).toBeGreaterThan(vertices[2]!);
  levels.forEach(({ json }, l) => {
    expect(json.nodes.find((n) => n.name === `${stem}_LOD${l}`)?.extras?.sylva_lod?.level).toBe(l);
  });

  // The impostor: no required extension, its atlas embedded as the base colour texture.
  const impostor = parse(files[names[3]!]!);
  expect(impostor.json.extensionsRequired).toBeUndefined();
  const textureIndex = impostor.json.materials?.[0]?.pbrMetallicRoughness?.baseColorTexture?.index;
  const image = impostor.json.images?.[impostor.json.textures?.[textureIndex ?? -1]?.source ?? -1];
  expect(image?.mimeType).toBe('image/png');
  const view = impostor.json.bufferViews[image!.bufferView]!;
  const png = impostor.bin.subarray(view.byteOffset ?? 0, (view.byteOffset ?? 0) + view.byteLength);
  const atlas = impostor.json.nodes.find((n) => n.name === `${stem}_impostor`)?.extras
    ?.sylva_impostor as { frames: number; crossed_quads: { frame: [number, number] }[] };
  expect(atlas.frames).toBe(8);
  // Every crossed quad's frame shows the tree: part of it covered, not all of it.
  const cover = await frameCover(
    page,
    png,
    atlas.frames,
    atlas.crossed_quads.map((q) => q.frame),
  );
  expect(cover).toHaveLength(4);
  for (const c of cover) {
    expect(c).toBeGreaterThan(0.05);
    expect(c).toBeLessThan(0.9);
  }
  expect(errors).toEqual([]);
});
