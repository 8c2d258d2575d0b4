/**
 * Every page of the build keeps the app's Content-Security-Policy (embed, docs, element demo),
 * and nothing stops other sites from framing the embed page.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { parsePolicy, policyOfHtml } from '../security/csp';

const webRoot = fileURLToPath(new URL('../..', import.meta.url));
const read = (path: string) => readFileSync(join(webRoot, path), 'utf8');
const appPolicy = policyOfHtml(read('index.html'));

describe('pages', () => {
  for (const page of ['embed.html', 'docs.html', 'public/element-demo.html']) {
    it(`${page} has the same CSP as index.html and no inline script or style`, () => {
      const html = read(page);
      expect(appPolicy).not.toBeNull();
      expect(policyOfHtml(html)).toBe(appPolicy);
      expect(html).not.toMatch(/<script(?![^>]*\bsrc=)[^>]*>/);
      expect(html).not.toMatch(/<style|\sstyle="/);
    });
  }

  it('the embed page can be framed: no frame-ancestors, no frame-busting', () => {
    const html = read('embed.html');
    expect(parsePolicy(policyOfHtml(html) ?? '').has('frame-ancestors')).toBe(false);
    expect(html).not.toMatch(/http-equiv="X-Frame-Options"/i);
    expect(read('src/embed/main.ts')).not.toMatch(/window\.top|parent\.location/);
  });

  it('the "Open in Sylva" link opens a new tab without an opener', () => {
    const html = read('embed.html');
    expect(html).toMatch(/id="open-in-sylva"[\s\S]*target="_blank"[\s\S]*rel="noopener"/);
  });
});
