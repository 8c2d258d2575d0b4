// The leaf sheet of the gallery: for every leaf preset, its SVG (outline, petiole, veins; from
// `sylva leaf --svg`) and its rendered blade (the LOD0 mesh from `sylva leaf --obj`, lit and drawn
// in Chromium), written to docs/gallery/leaves/ with docs/gallery-leaves.md listing them by
// species name. Run `node scripts/gallery-leaves.mjs`; `npm run gallery` calls `galleryLeaves()`.
// It builds only the native CLI and starts (and closes) its own browser; no server.
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright';
import { CHROMIUM_ARGS, chromiumPath } from './chromium.mjs';
import { nativeCli } from './native-cli.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));

/** Size (px) of each rendered blade. */
const SIZE = 360;

/** Positions, normals and triangles of an OBJ (`v`, `vn`, `f a//a b//b c//c` or `f a/t/n ...`). */
export function parseObj(text) {
  const v = [];
  const faces = [];
  for (const line of text.split('\n')) {
    const [kind, ...rest] = line.trim().split(/\s+/);
    if (kind === 'v') v.push(rest.map(Number));
    else if (kind === 'f') faces.push(rest.map((r) => Number(r.split('/')[0]) - 1));
  }
  return { v, faces };
}

/** Draws a mesh (leaf units) as a lit blade seen from the front, tilted 25° back. In the page. */
/* global document */
function drawBlade({ v, faces, size }) {
  const canvas = document.createElement('canvas');
  canvas.width = size;
  canvas.height = size;
  const ctx = canvas.getContext('2d');
  ctx.fillStyle = '#ffffff';
  ctx.fillRect(0, 0, size, size);
  const tilt = (25 * Math.PI) / 180;
  const p = v.map(([x, y, z]) => [
    x,
    y * Math.cos(tilt) - z * Math.sin(tilt),
    y * Math.sin(tilt) + z * Math.cos(tilt),
  ]);
  const xs = p.map((q) => q[0]);
  const ys = p.map((q) => q[1]);
  const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const scale = (0.9 * size) / Math.max(x1 - x0, y1 - y0, 1e-6);
  const cx = size / 2 - ((x0 + x1) / 2) * scale;
  const cy = size / 2 + ((y0 + y1) / 2) * scale;
  const light = [0.35, 0.55, 0.76];
  const tris = faces
    .map((f) => f.map((i) => p[i]))
    .filter((t) => t.length === 3 && t.every(Boolean))
    .sort((a, b) => a[0][2] + a[1][2] + a[2][2] - (b[0][2] + b[1][2] + b[2][2]));
  for (const [a, b, c] of tris) {
    const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    const n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    const len = Math.hypot(...n) || 1;
    const lit = Math.abs((n[0] * light[0] + n[1] * light[1] + n[2] * light[2]) / len);
    const k = 0.45 + 0.55 * lit;
    ctx.fillStyle = `rgb(${Math.round(70 * k)}, ${Math.round(140 * k)}, ${Math.round(50 * k)})`;
    ctx.strokeStyle = ctx.fillStyle;
    ctx.beginPath();
    ctx.moveTo(cx + a[0] * scale, cy - a[1] * scale);
    ctx.lineTo(cx + b[0] * scale, cy - b[1] * scale);
    ctx.lineTo(cx + c[0] * scale, cy - c[1] * scale);
    ctx.closePath();
    ctx.fill();
    ctx.stroke();
  }
  return canvas.toDataURL('image/png');
}

/**
 * Writes the leaf sheet: `docs/gallery/leaves/{name}.svg` and `{name}.png` per leaf preset and
 * `docs/gallery-leaves.md`. Returns the presets drawn (`[{name, label, description}]`).
 */
export async function galleryLeaves({ outDir = join(root, 'docs') } = {}) {
  const cli = nativeCli();
  const presets = JSON.parse(execFileSync(cli, ['leaf-presets'], { encoding: 'utf8' }));
  const dir = join(outDir, 'gallery', 'leaves');
  mkdirSync(dir, { recursive: true });
  const browser = await chromium.launch({ executablePath: chromiumPath(), args: CHROMIUM_ARGS });
  try {
    const page = await browser.newPage();
    for (const preset of presets) {
      const svg = join(dir, `${preset.name}.svg`);
      const obj = join(dir, `${preset.name}.obj`);
      execFileSync(cli, ['leaf', '--preset', preset.name, '--svg', svg, '--obj', obj], {
        stdio: ['ignore', 'ignore', 'inherit'],
      });
      const mesh = parseObj(readFileSync(obj, 'utf8'));
      execFileSync('rm', ['-f', obj]);
      const url = await page.evaluate(drawBlade, { ...mesh, size: SIZE });
      writeFileSync(join(dir, `${preset.name}.png`), Buffer.from(url.split(',')[1], 'base64'));
    }
  } finally {
    await browser.close();
  }
  const rows = presets.map(
    (p) =>
      `| **${p.label}** (\`${p.name}\`) | <img src="gallery/leaves/${p.name}.svg" width="220"> | <img src="gallery/leaves/${p.name}.png" width="220"> | ${p.description} |`,
  );
  const md = [
    '# Leaf sheet',
    '',
    "Every leaf preset: the inspector's drawing (outline, petiole, veins) and the rendered blade (the",
    'LOD0 mesh the trees instance, with its petiole). Written by `node scripts/gallery-leaves.mjs`; the',
    'models and their references are in [leaves.md](leaves.md).',
    '',
    '| species | drawing | blade | what makes it that leaf |',
    '|---|---|---|---|',
    ...rows,
    '',
  ].join('\n');
  writeFileSync(join(outDir, 'gallery-leaves.md'), md);
  return presets.map(({ name, label, description }) => ({ name, label, description }));
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const drawn = await galleryLeaves();
  console.log(`leaf sheet: ${drawn.length} leaves in docs/gallery/leaves/, docs/gallery-leaves.md`);
}
