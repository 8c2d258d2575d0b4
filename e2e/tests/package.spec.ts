// The npm package as a three.js developer gets it: the packed tarball (built by `npm run package`,
// or here when missing) installed with three and Vite into a fresh folder outside the repository,
// the example app (e2e/package-example, the README's API) built with Vite and served, and two
// trees checked in Chromium: both drawn in one scene, set() changes the hash, dispose() leaves no
// geometry or texture on the GPU; its subpath entries (`sylva-trees/core` ...) resolve to built,
// typed files. Prints the tarball size and the time to the first tree. Then the same tarball
// without a bundler: its dist/ and three in a plain page with an import map.
import { expect, test } from '@playwright/test';
import { execFileSync } from 'node:child_process';
import {
  cpSync,
  existsSync,
  mkdtempSync,
  readdirSync,
  readFileSync,
  rmSync,
  statSync,
} from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { freePort, serve } from '../../scripts/preview-server.mjs';

const root = fileURLToPath(new URL('../..', import.meta.url));
const example = fileURLToPath(new URL('../package-example', import.meta.url));

/** The tarball at the repository root, packed now if there is none. */
function tarball(): string {
  const find = (): string | undefined =>
    readdirSync(root).find((f) => /^sylva-trees-.*\.tgz$/.test(f));
  if (!find()) execFileSync('bash', ['scripts/package.sh'], { cwd: root, stdio: 'inherit' });
  const name = find();
  if (!name) throw new Error('npm run package wrote no tarball');
  return join(root, name);
}

/** The version of a dependency the repository uses (the example installs the same). */
function versionOf(name: string): string {
  const path = join(root, 'node_modules', name, 'package.json');
  return (JSON.parse(readFileSync(path, 'utf8')) as { version: string }).version;
}

/** The subpath entries of the package's `exports` (the root entry aside). */
const SUBPATHS = ['core', 'url', 'viewer', 'worker', 'worker-script'];

/**
 * Run by Node in the installed example: whether each entry resolves to a file of the package, the
 * pure ones (`core`, `url`) load, and what resolving the workspace-only `testing` entry throws.
 */
const ENTRY_PROBE = `
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
const out = {};
for (const s of ${JSON.stringify(['sylva-trees', ...SUBPATHS.map((s) => `sylva-trees/${s}`)])})
  out[s] = existsSync(fileURLToPath(import.meta.resolve(s)));
const core = await import('sylva-trees/core');
const url = await import('sylva-trees/url');
out.pure = typeof core.defaultParams === 'function' && typeof url.encodeParams === 'function';
try {
  import.meta.resolve('sylva-trees/testing');
  out.testing = 'resolved';
} catch (e) {
  out.testing = e.code;
}
console.log(JSON.stringify(out));
`;

test('the packed package works in a fresh three.js + Vite app', async ({ page }) => {
  test.setTimeout(180_000);
  const tgz = tarball();
  const size = statSync(tgz).size;
  console.log(`[package] ${tgz.split('/').pop()}: ${(size / 1024).toFixed(0)} kB`);
  expect(size).toBeLessThan(1.5 * 1024 * 1024);

  const t0 = Date.now();
  const phase = (name: string): void => console.log(`[package] ${name}: ${Date.now() - t0} ms`);
  const dir = mkdtempSync(join(tmpdir(), 'sylva-trees-example-'));
  let server: { url: string; stop(): Promise<void> } | null = null;
  try {
    cpSync(example, dir, { recursive: true });
    const npm = (args: string[]): void => {
      execFileSync('npm', args, { cwd: dir, stdio: 'pipe', timeout: 120_000 });
    };
    npm([
      'install',
      '--prefer-offline',
      '--no-audit',
      '--no-fund',
      '--no-package-lock',
      tgz,
      `three@${versionOf('three')}`,
      `vite@${versionOf('vite')}`,
    ]);
    phase('installed');
    execFileSync(join(dir, 'node_modules', '.bin', 'vite'), ['build'], { cwd: dir, stdio: 'pipe' });
    const built = readdirSync(join(dir, 'dist', 'assets'));
    // The bundler followed the package's worker and wasm URLs and emitted both.
    expect(built.some((f) => f.endsWith('.wasm'))).toBe(true);
    expect(built.some((f) => /^worker-.*\.js$/.test(f))).toBe(true);
    expect(
      existsSync(join(dir, 'node_modules', 'sylva-trees', 'dist', 'types', 'index.d.ts')),
    ).toBe(true);
    // The subpath entries: built, typed, loadable; `sylva-trees/testing` is not published.
    const types = join(dir, 'node_modules', 'sylva-trees', 'dist', 'types');
    for (const s of SUBPATHS.filter((s) => s !== 'worker-script'))
      expect(existsSync(join(types, s, 'index.d.ts')), s).toBe(true);
    const probe = execFileSync('node', ['--input-type=module', '-e', ENTRY_PROBE], {
      cwd: dir,
      encoding: 'utf8',
    });
    expect(JSON.parse(probe)).toEqual({
      'sylva-trees': true,
      ...Object.fromEntries(SUBPATHS.map((s) => [`sylva-trees/${s}`, true])),
      pure: true,
      testing: 'ERR_PACKAGE_PATH_NOT_EXPORTED',
    });

    phase('built');
    server = await serve(await freePort(), { outDir: join(dir, 'dist') });
    const errors: string[] = [];
    page.on('pageerror', (error) => errors.push(error.message));
    await page.setViewportSize({ width: 640, height: 360 });
    await page.goto(server.url);
    await expect(page.locator('body[data-ready="1"]')).toBeAttached({ timeout: 90_000 });
    const timing = await page.evaluate(() => {
      const w = window as unknown as { __example: { firstTreeMs: number; bothMs: number } };
      return { first: w.__example.firstTreeMs, both: w.__example.bothMs };
    });
    console.log(
      `[package] example app: first tree ${Math.round(timing.first)} ms, both trees ${Math.round(timing.both)} ms after navigation`,
    );

    phase('trees shown');
    await page.evaluate(() =>
      (window as unknown as { __example: { pause(): void } }).__example.pause(),
    );
    type Api = {
      pause(): void;
      stats(): { vertices: number; triangles: number; leaves: number; hash: string }[];
      treePixels(): [number, number];
      set(values: Record<string, number>): Promise<string>;
      glbBytes(): Promise<number>;
      dispose(): { geometries: number; textures: number; children: number };
    };
    const stats = await page.evaluate(() =>
      (window as unknown as { __example: Api }).__example.stats(),
    );
    for (const s of stats) {
      expect(s.vertices).toBeGreaterThan(1000);
      expect(s.leaves).toBeGreaterThan(100);
      expect(s.hash).toMatch(/^[0-9a-f]{16}$/);
    }
    expect(stats[0]?.hash).not.toBe(stats[1]?.hash);

    // Two trees in one scene: tree pixels in both halves of the frame.
    const [left, right] = await page.evaluate(() =>
      (window as unknown as { __example: Api }).__example.treePixels(),
    );
    expect(left).toBeGreaterThan(2000);
    expect(right).toBeGreaterThan(2000);
    await page.screenshot({ path: test.info().outputPath('two-trees.png') });
    phase('drawn');

    const before = stats[0]?.hash;
    const after = await page.evaluate(() =>
      (window as unknown as { __example: Api }).__example.set({ seed: 8 }),
    );
    expect(after).toMatch(/^[0-9a-f]{16}$/);
    expect(after).not.toBe(before);
    expect(
      await page.evaluate(() => (window as unknown as { __example: Api }).__example.glbBytes()),
    ).toBeGreaterThan(100_000);
    phase('set and exported');

    const memory = await page.evaluate(() =>
      (window as unknown as { __example: Api }).__example.dispose(),
    );
    expect(memory.geometries).toBe(0);
    // three's own split-sum lookup table for physically based materials (r182 and newer) stays.
    expect(memory.textures).toBeLessThanOrEqual(1);
    // The lights stay; the trees left the scene.
    expect(memory.children).toBe(2);
    expect(errors).toEqual([]);
  } finally {
    await server?.stop();
    rmSync(dir, { recursive: true, force: true });
  }
});

test('the packed package works without a bundler, through an import map', async ({ page }) => {
  test.setTimeout(120_000);
  // As the package README says: the tarball's dist/ copied to the site, three from its build,
  // both found by an import map in a plain page (e2e/package-importmap); no npm, no Vite.
  const dir = mkdtempSync(join(tmpdir(), 'sylva-trees-importmap-'));
  let server: { url: string; stop(): Promise<void> } | null = null;
  try {
    cpSync(fileURLToPath(new URL('../package-importmap', import.meta.url)), dir, {
      recursive: true,
    });
    execFileSync('tar', ['xzf', tarball(), '-C', dir]);
    cpSync(join(dir, 'package', 'dist'), join(dir, 'vendor', 'sylva-trees'), { recursive: true });
    cpSync(join(root, 'node_modules', 'three', 'build'), join(dir, 'vendor', 'three'), {
      recursive: true,
    });
    server = await serve(await freePort(), { outDir: dir });
    const errors: string[] = [];
    page.on('pageerror', (error) => errors.push(error.message));
    await page.goto(server.url);
    await expect(page.locator('body[data-ready="1"]')).toBeAttached({ timeout: 90_000 });
    const result = await page.evaluate(
      () =>
        (
          window as unknown as {
            __importMap: {
              stats?: { hash: string; leaves: number };
              presets?: number;
              error?: string;
            };
          }
        ).__importMap,
    );
    expect(result.error).toBeUndefined();
    expect(result.stats?.hash).toMatch(/^[0-9a-f]{16}$/);
    expect(result.stats?.leaves).toBeGreaterThan(100);
    expect(result.presets).toBeGreaterThan(10);
    // The tree is drawn: many pixels of the white page are not white.
    const drawn = await page.evaluate(() => {
      const canvas = document.querySelector('canvas');
      const gl = canvas?.getContext('webgl2');
      if (!canvas || !gl) return 0;
      const px = new Uint8Array(canvas.width * canvas.height * 4);
      gl.readPixels(0, 0, canvas.width, canvas.height, gl.RGBA, gl.UNSIGNED_BYTE, px);
      let n = 0;
      for (let i = 0; i < px.length; i += 4) if (px[i]! + px[i + 1]! + px[i + 2]! < 600) n++;
      return n;
    });
    expect(drawn).toBeGreaterThan(2000);
    expect(errors).toEqual([]);
  } finally {
    await server?.stop();
    rmSync(dir, { recursive: true, force: true });
  }
});
