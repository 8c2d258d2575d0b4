/**
 * The growth exports of the Export menu: the GLB with the growth animation and the zip of one
 * GLB per year are the native CLI's bytes (`--growth-animation`, `--growth-years`), and three.js
 * plays the animation from the GLB alone (GLTFLoader, AnimationMixer): its clip lasts the Age,
 * mid-way the morph influences are on and the tree is smaller than at the end.
 */
import { expect, test, type Download, type Page } from '@playwright/test';
import { unzipSync } from 'fflate';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { nativeCli } from '../../scripts/native-cli.mjs';
import { bareGlbPage, waitForTree, watchErrors } from './helpers';

/** A small young tree: two levels at Age 12 of 40. */
const AGE = 12;
const QUERY = `v=1&seed=5&levels=2&age=${AGE}`;
const CLI_TREE = ['--seed', '5', '--set', 'levels=2', '--age', String(AGE)];

/** Clicks an Export menu item and returns the download it starts. */
async function exportItem(page: Page, testId: string): Promise<Download> {
  await page.getByTestId('export-menu').click();
  const downloaded = page.waitForEvent('download');
  await page.getByTestId(testId).click();
  return downloaded;
}

/** The file `sylva generate CLI_TREE ARGS` writes at the path `--out` or `--growth-years` takes. */
function cli(args: string[], name: string): Buffer {
  const dir = mkdtempSync(join(tmpdir(), 'sylva-e2e-growth-'));
  try {
    const file = join(dir, name);
    const at = args.indexOf('FILE');
    const full = [...CLI_TREE, ...args.slice(0, at), file, ...args.slice(at + 1)];
    execFileSync(nativeCli(), ['generate', ...full], { stdio: 'ignore' });
    return readFileSync(file);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

test('GLB with growth animation and GLB per year: the CLI files; three.js plays the growth', async ({
  page,
}) => {
  test.setTimeout(240_000);
  const errors = watchErrors(page);
  await page.goto(`/?${QUERY}`);
  await waitForTree(page);
  await page.getByTestId('export-menu').click();
  await expect(page.getByTestId('export-glb-growth')).toContainText('GLB with growth animation');
  await expect(page.getByTestId('export-glb-growth-hint')).toContainText('year 0');
  await expect(page.getByTestId('export-glb-years')).toContainText('GLB per year (zip)');
  await expect(page.getByTestId('export-glb-growth')).toBeEnabled();
  await expect(page.getByTestId('export-glb-years')).toBeEnabled();
  await page.getByTestId('export-menu').click();

  const growth = await exportItem(page, 'export-glb-growth');
  expect(growth.suggestedFilename()).toMatch(/-growth\.glb$/);
  const glb = readFileSync(await growth.path());
  expect(glb.equals(cli(['--growth-animation', '--out', 'FILE'], 'tree.glb'))).toBe(true);

  const years = await exportItem(page, 'export-glb-years');
  expect(years.suggestedFilename()).toMatch(/-years\.zip$/);
  const zip = readFileSync(await years.path());
  expect(zip.equals(cli(['--leaves', 'baked', '--growth-years', 'FILE'], 'years.zip'))).toBe(true);
  const files = unzipSync(new Uint8Array(zip));
  const names = Object.keys(files);
  expect(names).toHaveLength(AGE);
  expect(names[0]).toBe('year_001.glb');
  expect(names.at(-1)).toBe(`year_0${AGE}.glb`);
  await expect(page.getByTestId('toolbar-status')).toContainText('a GLB per year');
  expect(errors).toEqual([]);

  // The GLB alone in three.js: a bare page (no app) with GLTFLoader and an AnimationMixer.
  const r = (await bareGlbPage(page, 'growth-view', GROWTH_VIEW_HTML, glb)) as {
    error?: string;
    clips: number;
    duration: number;
    tracks: string[];
    mid: number[];
    end: number[];
    heights: number[];
    triangles: number;
  };
  expect(r.error).toBeUndefined();
  expect(r.clips).toBe(1);
  expect(r.duration).toBeCloseTo(AGE, 5);
  expect(r.tracks.sort()).toEqual(['bark.morphTargetInfluences', 'leaves.morphTargetInfluences']);
  // Mid-way between two keys the weight is shared between their targets; at the Age, none.
  expect(Math.max(...r.mid)).toBeGreaterThan(0.2);
  expect(r.mid.reduce((a, b) => a + b, 0)).toBeCloseTo(1, 3);
  expect(Math.max(...r.end)).toBe(0);
  // The bark's height (morphs applied) grows through the years.
  const [early, mid, end] = r.heights;
  expect(early).toBeLessThan(mid ?? 0);
  expect(mid).toBeLessThan(end ?? 0);
  // Drawn (the morphs in the renderer's shaders): the tree at half its Age.
  expect(r.triangles).toBeGreaterThan(1000);
  await page.screenshot({ path: test.info().outputPath('growth-glb.png') });
});

/** The bare three.js page: loads tree.glb, plays its animation at a few times, reports. */
const GROWTH_VIEW_HTML = `<!doctype html>
<html><head><meta charset="utf-8"><style>html,body{margin:0;background:#cfe3f0}</style>
<script type="importmap">{"imports":{"three":"/growth-view/three/build/three.module.js",
"three/addons/":"/growth-view/three/examples/jsm/"}}</script></head>
<body><script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
try {
  const gltf = await new GLTFLoader().loadAsync('/growth-view/tree.glb');
  const scene = new THREE.Scene();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x445533, 2.5), gltf.scene);
  const clip = gltf.animations[0];
  const mixer = new THREE.AnimationMixer(gltf.scene);
  // Played once and held at its end (a repeating clip wraps from the Age back to year 0).
  const action = mixer.clipAction(clip);
  action.setLoop(THREE.LoopOnce, 1);
  action.clampWhenFinished = true;
  action.play();
  const bark = gltf.scene.getObjectByName('bark');
  const mesh = bark.isMesh ? bark : bark.children.find((c) => c.isMesh);
  // Box3 with precise = true reads each vertex through getVertexPosition: morphs applied.
  const height = () => new THREE.Box3().setFromObject(mesh, true).max.y;
  const times = [0.2 * clip.duration, 0.5 * clip.duration, clip.duration];
  const heights = [];
  let mid = [];
  for (const t of times) {
    mixer.setTime(t);
    gltf.scene.updateMatrixWorld(true);
    heights.push(height());
    if (t === times[1]) {
      // Half-way between the two keys around mid-time.
      const keys = clip.tracks[0].times;
      const k = keys.findIndex((y) => y > t);
      mixer.setTime(0.5 * (keys[k - 1] + keys[k]));
      mid = [...mesh.morphTargetInfluences];
    }
  }
  const end = [...mesh.morphTargetInfluences];
  // The picture: the tree at half its Age.
  action.stop().play();
  mixer.setTime(0.5 * clip.duration);
  const camera = new THREE.PerspectiveCamera(40, innerWidth / innerHeight, 0.1, 200);
  camera.position.set(0, 0.5 * heights[2], 2.2 * heights[2]);
  camera.lookAt(0, 0.5 * heights[2], 0);
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setSize(innerWidth, innerHeight);
  renderer.setClearColor(0xcfe3f0);
  document.body.appendChild(renderer.domElement);
  renderer.render(scene, camera);
  window.report = {
    clips: gltf.animations.length,
    duration: clip.duration,
    tracks: clip.tracks.map((t) => t.name),
    mid,
    end,
    heights,
    triangles: renderer.info.render.triangles,
  };
} catch (e) {
  window.report = { error: String(e && e.stack || e) };
}
</script></body></html>`;
