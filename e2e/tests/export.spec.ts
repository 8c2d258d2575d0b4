/**
 * The app toolbar: PNG screenshot, preset JSON save → load, the GLB for engines, the GLB for
 * editors and the zipped OBJ (both GLBs the same bytes as the
 * native CLI's, the baked one drawn by three.js), "Copy embed code" and the docs link.
 */
import { expect, test, type Download, type Page } from '@playwright/test';
import { unzipSync } from 'fflate';
import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { nativeCli } from '../../scripts/native-cli.mjs';
import { bareGlbPage, waitForNewTree, waitForTree, watchErrors } from './helpers';

const QUERY = 'v=1&seed=5&levels=2';

async function bytesOf(download: Download): Promise<Buffer> {
  const path = await download.path();
  return readFileSync(path);
}

/** Clicks an Export menu item and returns the download it starts. */
async function exportItem(page: Page, testId: string): Promise<Download> {
  await page.getByTestId('export-menu').click();
  const downloaded = page.waitForEvent('download');
  await page.getByTestId(testId).click();
  return downloaded;
}

test('PNG screenshot and preset JSON save → load', async ({ page }) => {
  const errors = watchErrors(page);
  await page.goto(`/?${QUERY}`);
  const hash = await waitForTree(page);

  const png = await exportItem(page, 'export-png');
  expect(png.suggestedFilename()).toMatch(/^sylva-.*\.png$/);
  const image = await bytesOf(png);
  expect([...image.subarray(0, 8)]).toEqual([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  // IHDR: the size of the canvas drawing buffer.
  const size = await page
    .getByTestId('viewer-canvas')
    .evaluate((c) => [(c as HTMLCanvasElement).width, (c as HTMLCanvasElement).height]);
  expect([image.readUInt32BE(16), image.readUInt32BE(20)]).toEqual(size);
  expect(image.length).toBeGreaterThan(5000);
  await expect(page.getByTestId('toolbar-status')).toContainText('.png');

  const saved = await exportItem(page, 'export-preset-save');
  expect(saved.suggestedFilename()).toMatch(/^sylva-.*seed5\.json$/);
  const text = (await bytesOf(saved)).toString('utf8');
  const data = JSON.parse(text) as { sylva: number; params: Record<string, number> };
  expect(data.sylva).toBe(1);
  expect(data.params.seed).toBe(5);
  expect(data.params.levels).toBe(2);
  expect(Object.keys(data.params).length).toBeGreaterThan(50);

  // Another tree, then load the file: the saved tree comes back (same hash, same URL).
  const seedField = page.getByTestId('param-number-seed');
  await seedField.fill('9');
  await seedField.press('Enter');
  await waitForNewTree(page, hash);
  await page
    .getByTestId('preset-file-input')
    .setInputFiles({ name: 'tree.json', mimeType: 'application/json', buffer: Buffer.from(text) });
  await expect(page.getByTestId('stat-hash')).toHaveText(hash);
  await expect(seedField).toHaveValue('5');
  await expect(page.getByTestId('toolbar-status')).toContainText('Loaded tree.json');
  await expect.poll(() => new URL(page.url()).searchParams.get('seed')).toBe('5');

  // A bad file is refused with a message; the tree stays.
  await page.getByTestId('preset-file-input').setInputFiles({
    name: 'bad.json',
    mimeType: 'application/json',
    buffer: Buffer.from('{"sylva":1,"params":{"levels":99}}'),
  });
  const status = page.getByTestId('toolbar-status');
  await expect(status).toHaveAttribute('role', 'alert');
  await expect(status).toContainText('Could not load "bad.json"');
  await expect(status).toContainText('Levels (levels)');
  await page.getByTestId('preset-file-input').setInputFiles({
    name: 'notes.json',
    mimeType: 'application/json',
    buffer: Buffer.from('hello'),
  });
  await expect(status).toContainText('not JSON');
  await expect(page.getByTestId('stat-hash')).toHaveText(hash);
  await expect(page.getByTestId('error-banner')).toHaveCount(0);
  expect(errors).toEqual([]);
});

/** The native CLI's GLB of the app's `QUERY` tree (seed 5, two levels) with `leaves`. */
function cliGlb(leaves: 'instanced' | 'baked' | 'strict'): Buffer {
  const dir = mkdtempSync(join(tmpdir(), 'sylva-e2e-glb-'));
  try {
    const file = join(dir, 'tree.glb');
    execFileSync(
      nativeCli(),
      [
        'generate',
        '--seed',
        '5',
        '--set',
        'levels=2',
        ...(leaves === 'strict' ? ['--strict'] : ['--leaves', leaves]),
        '--out',
        file,
      ],
      { stdio: 'ignore' },
    );
    return readFileSync(file);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

test('GLB and OBJ export follow the core', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = watchErrors(page);
  await page.goto(`/?${QUERY}`);
  await waitForTree(page);
  await page.getByTestId('export-menu').click();
  const glb = page.getByTestId('export-glb');
  const baked = page.getByTestId('export-glb-baked');
  const obj = page.getByTestId('export-obj');
  // The two GLBs say what they are for and when to choose them.
  await expect(glb).toContainText('GLB for engines (instanced leaves)');
  await expect(page.getByTestId('export-glb-hint')).toContainText('three.js');
  await expect(baked).toContainText(
    'GLB for Blender and other editors (leaves merged into one mesh)',
  );
  await expect(page.getByTestId('export-glb-baked-hint')).toContainText('Blender');
  await expect(page.getByTestId('export-glb-strict')).toContainText(
    'GLB for Godot and strict importers',
  );
  await expect(glb).toBeEnabled();
  await expect(baked).toBeEnabled();
  await expect(obj).toBeEnabled();
  await page.getByTestId('export-menu').click();
  // Both GLBs: the same bytes as the native CLI for the same parameters.
  const file = await bytesOf(await exportItem(page, 'export-glb'));
  expect(file.subarray(0, 4).toString('latin1')).toBe('glTF');
  expect(file.readUInt32LE(8)).toBe(file.length);
  expect(file.equals(cliGlb('instanced'))).toBe(true);
  const bakedDownload = await exportItem(page, 'export-glb-baked');
  expect(bakedDownload.suggestedFilename()).toMatch(/\.glb$/);
  const bakedFile = await bytesOf(bakedDownload);
  expect(bakedFile.equals(cliGlb('baked'))).toBe(true);
  const json = JSON.parse(bakedFile.subarray(20, 20 + bakedFile.readUInt32LE(12)).toString()) as {
    extensionsUsed?: string[];
    meshes: { name: string; primitives: { attributes: Record<string, number> }[] }[];
  };
  expect(json.extensionsUsed ?? []).not.toContain('EXT_mesh_gpu_instancing');
  const leaves = json.meshes.find((m) => m.name === 'leaves');
  expect(Object.keys(leaves?.primitives[0]?.attributes ?? {})).toEqual(
    expect.arrayContaining(['COLOR_0', '_WIND_PIVOT', '_WIND_PARAMS']),
  );
  await expect(page.getByTestId('toolbar-status')).toContainText('.glb');
  // The strict GLB: the CLI's --strict bytes, no extension listed.
  const strictDownload = await exportItem(page, 'export-glb-strict');
  expect(strictDownload.suggestedFilename()).toMatch(/-strict\.glb$/);
  const strictFile = await bytesOf(strictDownload);
  expect(strictFile.equals(cliGlb('strict'))).toBe(true);
  const strictJson = JSON.parse(
    strictFile.subarray(20, 20 + strictFile.readUInt32LE(12)).toString(),
  ) as { extensionsUsed?: string[]; extensionsRequired?: string[] };
  expect(strictJson.extensionsUsed).toBeUndefined();
  expect(strictJson.extensionsRequired).toBeUndefined();

  const zip = await exportItem(page, 'export-obj');
  expect(zip.suggestedFilename()).toMatch(/-obj\.zip$/);
  const archive = unzipSync(new Uint8Array(await bytesOf(zip)));
  const names = Object.keys(archive);
  expect(names.some((n) => n.endsWith('.obj'))).toBe(true);
  const objName = names.find((n) => n.endsWith('.obj')) ?? '';
  const mtlName = names.find((n) => n.endsWith('.mtl')) ?? '';
  expect(new TextDecoder().decode(archive[objName])).toMatch(/\nv -?\d/);
  expect(new TextDecoder().decode(archive[mtlName])).toContain('newmtl');
  await expect(page.getByTestId('toolbar-status')).toContainText('OBJ, MTL and textures');
  expect(errors).toEqual([]);
});

test("the baked GLB in three.js: leaves in the crown, tinted, with their twigs' wind", async ({
  page,
}) => {
  const glb = cliGlb('baked');
  const r = (await bareGlbPage(page, 'baked-view', BAKED_VIEW_HTML, glb)) as {
    error?: string;
    leafVertices: number;
    leafBox: number[];
    barkBox: number[];
    tint: number[];
    windLevels: number[];
    hasTexture: boolean;
  };
  expect(r.error).toBeUndefined();
  expect(r.leafVertices).toBeGreaterThan(1000);
  expect(r.hasTexture).toBe(true);
  // The leaves sit in the crown: within the bark's box grown by half a metre, and above its foot.
  const [lx0, ly0, lz0, lx1, ly1, lz1] = r.leafBox;
  const [bx0, by0, bz0, bx1, by1, bz1] = r.barkBox;
  for (const [inner, outer] of [
    [lx0, (bx0 ?? 0) - 0.5],
    [ly0, by0 ?? 0],
    [lz0, (bz0 ?? 0) - 0.5],
  ] as const) {
    expect(inner).toBeGreaterThanOrEqual(outer);
  }
  for (const [inner, outer] of [
    [lx1, (bx1 ?? 0) + 0.5],
    [ly1, (by1 ?? 0) + 0.5],
    [lz1, (bz1 ?? 0) + 0.5],
  ] as const) {
    expect(inner).toBeLessThanOrEqual(outer);
  }
  // Tinted (the crown's shade: some leaves darker than others) and hung on twigs (level >= 1).
  const [tmin, tmax] = r.tint;
  expect((tmax ?? 0) - (tmin ?? 0)).toBeGreaterThan(0.1);
  expect(Math.min(...r.windLevels)).toBeGreaterThanOrEqual(1);
  await page.screenshot({ path: test.info().outputPath('baked-glb.png') });
  const shot = test.info().outputPath('baked-glb.png');
  await test.info().attach('baked GLB in three.js', { path: shot, contentType: 'image/png' });
  if (process.env.SYLVA_E2E_SHOT) copyFileSync(shot, process.env.SYLVA_E2E_SHOT);
});

/** The bare three.js page of the baked-GLB test: loads tree.glb, draws it, reports on it. */
const BAKED_VIEW_HTML = `<!doctype html>
<html><head><meta charset="utf-8"><style>html,body{margin:0;background:#cfe3f0}</style>
<script type="importmap">{"imports":{"three":"/baked-view/three/build/three.module.js",
"three/addons/":"/baked-view/three/examples/jsm/"}}</script></head>
<body><script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
try {
  const gltf = await new GLTFLoader().loadAsync('/baked-view/tree.glb');
  const scene = new THREE.Scene();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x445533, 2.5));
  const sun = new THREE.DirectionalLight(0xffffff, 2);
  sun.position.set(3, 8, 5);
  scene.add(sun, gltf.scene);
  const leaves = gltf.scene.getObjectByName('leaves');
  const bark = gltf.scene.getObjectByName('bark');
  const box = (o) => { const b = new THREE.Box3().setFromObject(o); return [...b.min.toArray(), ...b.max.toArray()]; };
  const g = leaves.geometry;
  const color = g.getAttribute('color');
  const lum = [];
  for (let i = 0; i < color.count; i += 97) lum.push((color.getX(i) + color.getY(i) + color.getZ(i)) / 3);
  const pivot = g.getAttribute('_wind_pivot');
  const doc = leaves.userData.wind_attributes._WIND_PIVOT;
  const levels = [];
  for (let i = 0; i < pivot.count; i += 97) levels.push(Math.round(doc.offset[3] + doc.scale[3] * pivot.getW(i)));
  const all = new THREE.Box3().setFromObject(gltf.scene);
  const size = all.getSize(new THREE.Vector3());
  const centre = all.getCenter(new THREE.Vector3());
  const camera = new THREE.PerspectiveCamera(40, innerWidth / innerHeight, 0.1, 200);
  const d = Math.max(size.x, size.y, size.z) * 1.6;
  camera.position.set(centre.x + d * 0.6, centre.y + d * 0.15, centre.z + d * 0.8);
  camera.lookAt(centre);
  const renderer = new THREE.WebGLRenderer({ antialias: true });
  renderer.setSize(innerWidth, innerHeight);
  renderer.setClearColor(0xcfe3f0);
  document.body.appendChild(renderer.domElement);
  renderer.render(scene, camera);
  window.report = {
    leafVertices: g.getAttribute('position').count,
    leafBox: box(leaves),
    barkBox: box(bark),
    tint: [Math.min(...lum), Math.max(...lum)],
    windLevels: levels,
    hasTexture: !!leaves.material.map,
  };
} catch (e) {
  window.report = { error: String(e && e.stack || e) };
}
</script></body></html>`;

test('Copy embed code and the docs link', async ({ page, context, baseURL }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.goto(`/?${QUERY}`);
  await waitForTree(page);
  await expect(page.getByTestId('docs-link')).toHaveAttribute('href', 'docs.html');
  // The docs (docs.html, docs/embedding.md) name the button by this label.
  await expect(page.getByTestId('copy-embed')).toHaveText('Copy embed code');
  await page.getByTestId('copy-embed').click();
  const dialog = page.getByTestId('embed-dialog');
  await expect(dialog).toBeVisible();
  await expect(page.getByTestId('embed-copied')).toContainText('copied');
  const iframe = await page.getByTestId('embed-iframe-code').inputValue();
  expect(iframe).toContain(`<iframe src="${baseURL}/embed.html?${QUERY.replace(/&/g, '&amp;')}"`);
  expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(iframe);

  await page.getByTestId('embed-autorotate').check();
  await page.getByTestId('embed-background').selectOption('transparent');
  await expect(page.getByTestId('embed-iframe-code')).toHaveValue(
    /autorotate=1&amp;bg=transparent/,
  );
  const element = await page.getByTestId('embed-element-code').inputValue();
  expect(element).toContain(`<script type="module" src="${baseURL}/sylva-tree.js"></script>`);
  expect(element).toContain(
    '<sylva-tree seed="5" params="levels=2" autorotate background="transparent"',
  );
  await page.getByTestId('copy-element').click();
  await expect(page.getByTestId('embed-copied')).toContainText('Element code copied');
  expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(element);
  await page.keyboard.press('Escape');
  await expect(dialog).toHaveCount(0);
});

test('the Export menu closes on Escape and on a press outside it', async ({ page }) => {
  const errors = watchErrors(page);
  await page.goto('/');
  await waitForTree(page);
  const menu = page.locator('details.toolbar-menu');
  const summary = page.getByTestId('export-menu');
  await summary.click();
  await expect(menu).toHaveAttribute('open', '');
  await page.keyboard.press('Escape');
  await expect(menu).not.toHaveAttribute('open', '');
  await expect(summary).toBeFocused();
  await summary.click();
  await expect(page.getByTestId('export-png')).toBeVisible();
  // A press on the tree (the canvas) closes it; one inside the menu does not.
  await page.getByTestId('export-png').hover();
  await page.locator('.toolbar-items').dispatchEvent('pointerdown');
  await expect(menu).toHaveAttribute('open', '');
  await page.mouse.click(60, 400);
  await expect(menu).not.toHaveAttribute('open', '');
  expect(errors).toEqual([]);
});
