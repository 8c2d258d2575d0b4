/**
 * Security checks of the sources: the CSP in index.html is strict, the dev nonce helper keeps
 * it, and nothing in the app can turn text into markup or code (no innerHTML, no eval).
 */
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { formatPolicy, parsePolicy, policyOfHtml, withNonce } from './csp';

const webRoot = fileURLToPath(new URL('../..', import.meta.url));
const indexHtml = readFileSync(join(webRoot, 'index.html'), 'utf8');

/** Every file under `dir` (recursively). */
function files(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? files(path) : [path];
  });
}

describe('Content-Security-Policy of index.html', () => {
  const text = policyOfHtml(indexHtml);
  const policy = parsePolicy(text ?? '');

  it('is present as a meta tag', () => {
    expect(text).not.toBeNull();
    expect(policy.size).toBeGreaterThan(5);
  });

  it('allows scripts from the site and wasm compilation only: no inline code, no eval', () => {
    expect(policy.get('script-src')).toEqual(["'self'", "'wasm-unsafe-eval'"]);
    expect(policy.get('default-src')).toEqual(["'self'"]);
    for (const [name, sources] of policy) {
      expect(sources, name).not.toContain("'unsafe-eval'");
      expect(sources, name).not.toContain("'unsafe-inline'");
      expect(sources, name).not.toContain('*');
      expect(
        sources.some((s) => s.startsWith('http')),
        name,
      ).toBe(false);
    }
  });

  it('pins workers, fetches, styles and images to the site, and disables plugins and forms', () => {
    expect(policy.get('worker-src')).toEqual(["'self'"]);
    expect(policy.get('connect-src')).toEqual(["'self'"]);
    expect(policy.get('style-src')).toEqual(["'self'"]);
    expect(policy.get('img-src')).toEqual(["'self'", 'data:', 'blob:']);
    expect(policy.get('object-src')).toEqual(["'none'"]);
    expect(policy.get('base-uri')).toEqual(["'self'"]);
    expect(policy.get('form-action')).toEqual(["'none'"]);
  });

  it('uses no directive that a meta tag ignores (the browser would log an error)', () => {
    for (const name of ['frame-ancestors', 'report-uri', 'report-to', 'sandbox']) {
      expect(policy.has(name), name).toBe(false);
    }
  });

  it('parse and format round-trip', () => {
    expect(parsePolicy(formatPolicy(policy))).toEqual(policy);
  });
});

describe('withNonce (dev server)', () => {
  it('adds the nonce to script-src and style-src and keeps everything else', () => {
    const html = withNonce(indexHtml, 'abc123+/=');
    const policy = parsePolicy(policyOfHtml(html) ?? '');
    expect(policy.get('script-src')).toEqual(["'self'", "'wasm-unsafe-eval'", "'nonce-abc123+/='"]);
    expect(policy.get('style-src')).toEqual(["'self'", "'nonce-abc123+/='"]);
    expect(policy.get('connect-src')).toEqual(["'self'"]);
    expect(html.replace(policyOfHtml(html) ?? '', '')).toBe(
      indexHtml.replace(policyOfHtml(indexHtml) ?? '', ''),
    );
  });

  it('refuses a page without a policy and a nonce that could break out of the attribute', () => {
    expect(() => withNonce('<html><head></head></html>', 'abc')).toThrow(/no Content-Security/);
    expect(() => withNonce(indexHtml, 'a" onload="x')).toThrow(/bad nonce/);
    expect(() => withNonce(indexHtml, "a'; script-src *")).toThrow(/bad nonce/);
  });
});

describe('no HTML or code from strings anywhere in the app', () => {
  // Built from pieces; this file itself names them in its titles and is not scanned.
  const forbidden = [
    ['dangerously', 'SetInnerHTML'],
    ['.inner', 'HTML'],
    ['.outer', 'HTML'],
    ['insertAdjacent', 'HTML'],
    ['document', '.write'],
    ['eval', '('],
    ['new ', 'Function'],
    ['createContextual', 'Fragment'],
  ].map((parts) => parts.join(''));
  const sources = [
    // The app's own code and the shared runtime of the `sylva-trees` package (and its wasm glue).
    ...[join(webRoot, 'src'), join(webRoot, '..', 'packages', 'sylva-trees', 'src')]
      .flatMap((dir) => files(dir))
      .filter((f) => /\.(ts|tsx|js|html)$/.test(f)),
    join(webRoot, 'index.html'),
  ].filter((f) => f !== fileURLToPath(import.meta.url));

  it('scans the app sources, the package runtime, the wasm glue and index.html', () => {
    expect(sources.length).toBeGreaterThan(20);
    expect(sources.some((f) => f.endsWith('sylva_wasm.js'))).toBe(true);
  });

  it('finds none of: dangerouslySetInnerHTML, innerHTML, outerHTML, eval, new Function', () => {
    const hits: string[] = [];
    for (const file of sources) {
      const text = readFileSync(file, 'utf8');
      for (const needle of forbidden) {
        if (text.includes(needle)) hits.push(`${relative(webRoot, file)}: ${needle}`);
      }
    }
    expect(hits).toEqual([]);
  });
});
