import { chromium } from 'playwright-core';
import { benchPaint } from './bench-edits.mjs';
import { CHROMIUM_ARGS, chromiumPath } from './chromium.mjs';
import { freePort, serve } from './preview-server.mjs';
const { url, stop } = await serve(await freePort());
const browser = await chromium.launch({ executablePath: chromiumPath(), args: CHROMIUM_ARGS });
try {
  for (let i = 0; i < Number(process.argv[2] ?? 2); i++) console.log(JSON.stringify(await benchPaint(browser, url)));
} finally { await browser.close(); await stop(); }
