// `npm run gallery`: renders the look of every preset, every broadleaf through the seasons,
// close-ups of flowers and fruit, growth over the years, close-ups of the details (bark types,
// a fork, a branch collar, a tree hole, a leaf cluster) and the Shape by hand tools before and
// after in the built app (web/dist, embed page, headless Chromium with software WebGL) into
// docs/gallery/*.png (palette PNGs, well under 150 KB each) and
// writes docs/gallery.md. Each section is a module in scripts/gallery/ with
// `{ id, title, intro, shots(ctx) }`; to add one, import it and append it to SECTIONS. The leaf
// sheet (scripts/gallery-leaves.mjs, docs/gallery-leaves.md) follows (`--only leaves` alone).
// `--only SECTION_ID` renders one section and rewrites only its part of docs/gallery.md.
//
// Usage: node scripts/gallery.mjs [--only SECTION_ID] [--presets a,b,c]
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, chromiumPath } from './chromium.mjs';
import { serve } from './preview-server.mjs';
import { galleryContext, markdown, updateSections } from './gallery/context.mjs';
import { closeupsSection } from './gallery/closeups.mjs';
import { handEditsSection } from './gallery/handEdits.mjs';
import { presetsSection } from './gallery/presets.mjs';
import { partsSection, seasonsSection } from './gallery/seasons.mjs';
import { growthSection } from './gallery/growth.mjs';
import { galleryLeaves } from './gallery-leaves.mjs';

/** The gallery's sections, in page order. */
export const SECTIONS = [
  presetsSection,
  seasonsSection,
  partsSection,
  growthSection,
  closeupsSection,
  handEditsSection,
];

const root = fileURLToPath(new URL('..', import.meta.url));
const PORT = 4393;

function argument(name) {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : undefined;
}

async function main() {
  const only = argument('--only');
  const presetFilter = argument('--presets')?.split(',');
  const outDir = `${root}/docs/gallery`;
  mkdirSync(outDir, { recursive: true });
  const { url, stop } = await serve(PORT);
  const browser = await chromium.launch({ executablePath: chromiumPath(), args: CHROMIUM_ARGS });
  try {
    const ctx = await galleryContext(browser, url, outDir, { presetFilter });
    const done = [];
    for (const section of SECTIONS) {
      if (only && section.id !== only) continue;
      const started = Date.now();
      const shots = await section.shots(ctx);
      console.log(
        `${section.id}: ${shots.length} images in ${((Date.now() - started) / 1000).toFixed(0)} s`,
      );
      done.push({ section, shots });
    }
    const page = `${root}/docs/gallery.md`;
    if (!presetFilter && !only) writeFileSync(page, markdown(done));
    // One section: only its part of the page changes.
    else if (!presetFilter && done.length) {
      writeFileSync(page, updateSections(readFileSync(page, 'utf8'), done, SECTIONS));
    }
  } finally {
    await browser.close();
    await stop();
  }
  // The leaf sheet (docs/gallery-leaves.md): every leaf preset's SVG and rendered blade.
  if (!only || only === 'leaves') await galleryLeaves();
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  main().catch((e) => {
    console.error(e);
    process.exit(1);
  });
}
