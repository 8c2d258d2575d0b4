/**
 * The app toolbar: PNG screenshot, preset JSON save → load, GLB/OBJ (when the core has the
 * exporters), "Copy embed code" and the docs link.
 */
import { expect, test, type Download, type Page } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { waitForNewTree, waitForTree, watchErrors } from './helpers';

const QUERY = 'v=1&seed=5&levels=2';

/** Whether the wasm core in web/src/wasm has the mesh exporters (the `export` branch). */
function coreHasExporters(): boolean {
  const dts = fileURLToPath(new URL('../../web/src/wasm/sylva_wasm.d.ts', import.meta.url));
  return /\bto_glb\(/.test(readFileSync(dts, 'utf8'));
}

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

test('GLB and OBJ export follow the core', async ({ page }) => {
  const errors = watchErrors(page);
  await page.goto(`/?${QUERY}`);
  await waitForTree(page);
  await page.getByTestId('export-menu').click();
  const glb = page.getByTestId('export-glb');
  const obj = page.getByTestId('export-obj');
  if (coreHasExporters()) {
    await expect(glb).toBeEnabled();
    await page.getByTestId('export-menu').click();
    const file = await bytesOf(await exportItem(page, 'export-glb'));
    expect(file.subarray(0, 4).toString('latin1')).toBe('glTF');
    expect(file.readUInt32LE(4)).toBe(2);
    expect(file.readUInt32LE(8)).toBe(file.length);
    const zip = await exportItem(page, 'export-obj');
    expect(zip.suggestedFilename()).toMatch(/\.zip$/);
    const archive = (await bytesOf(zip)).toString('latin1');
    expect(archive.startsWith('PK\x03\x04')).toBe(true);
    expect(archive).toMatch(/\nv -?\d/);
    expect(archive).toContain('newmtl');
  } else {
    // This core has no exporters yet: the items are offered but disabled, with the reason.
    await expect(glb).toBeDisabled();
    await expect(obj).toBeDisabled();
    await expect(glb).toHaveAttribute('title', /no exporter/);
  }
  expect(errors).toEqual([]);
});

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
