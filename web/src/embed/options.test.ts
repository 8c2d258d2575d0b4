/** Embed options, the "Open in Sylva" query and the embed snippets. */
import { describe, expect, it } from 'vitest';
import { defaultParams } from 'sylva-trees/core';
import { realRegistry } from 'sylva-trees/testing';
import { decodeQuery } from 'sylva-trees/url';
import {
  appQuery,
  elementSnippet,
  embedUrl,
  escapeAttribute,
  fatalQueryProblem,
  iframeSnippet,
  openInSylvaUrl,
  parseBackground,
  parseEmbedOptions,
  type SnippetInput,
} from './options';

const registry = realRegistry();

describe('parseEmbedOptions', () => {
  it('defaults: no autorotate, the default sky, no messages', () => {
    expect(parseEmbedOptions('?v=1&seed=7')).toEqual({
      autorotate: false,
      wind: true,
      background: { kind: 'default' },
      messages: [],
    });
  });

  it('reads autorotate and a transparent or coloured background', () => {
    expect(parseEmbedOptions('autorotate=1&bg=transparent')).toMatchObject({
      autorotate: true,
      background: { kind: 'transparent' },
    });
    expect(parseEmbedOptions('?autorotate=true&bg=%23ABC').background).toEqual({
      kind: 'color',
      color: '#aabbcc',
    });
    expect(parseEmbedOptions('bg=white&autorotate=0')).toMatchObject({
      autorotate: false,
      background: { kind: 'color', color: '#ffffff' },
    });
    expect(parseEmbedOptions('autorotate').autorotate).toBe(true);
  });

  it('wind is on unless wind=0 (a bad value is reported and keeps it on)', () => {
    expect(parseEmbedOptions('wind=0').wind).toBe(false);
    expect(parseEmbedOptions('wind=off&seed=2').wind).toBe(false);
    expect(parseEmbedOptions('wind=1').wind).toBe(true);
    const bad = parseEmbedOptions('wind=gale');
    expect(bad.wind).toBe(true);
    expect(bad.messages.join(' ')).toMatch(/Ignored "wind"/);
    expect(appQuery('v=1&seed=3&wind=0&autorotate=1')).toBe('v=1&seed=3');
  });

  it('reports hostile or unknown values and falls back to the defaults', () => {
    const o = parseEmbedOptions('bg=red;background:url(x)&autorotate=maybe');
    expect(o.autorotate).toBe(false);
    expect(o.background).toEqual({ kind: 'default' });
    expect(o.messages).toHaveLength(2);
    expect(o.messages.join(' ')).toMatch(/not a colour/);
    expect(parseBackground('</script><b>')).toMatch(/not a colour/);
    expect(parseBackground('constructor')).toMatch(/not a colour/);
    expect(parseBackground('%E0%A4%A')).toMatch(/not a colour/);
    expect(parseEmbedOptions('bg=%E0%A4%A').background).toEqual({ kind: 'default' });
  });
});

describe('fatalQueryProblem', () => {
  it('accepts v=1, no version, and the empty query', () => {
    expect(fatalQueryProblem('?v=1&seed=3')).toBeNull();
    expect(fatalQueryProblem('seed=3')).toBeNull();
    expect(fatalQueryProblem('')).toBeNull();
  });

  it('rejects another version and over-long queries', () => {
    expect(fatalQueryProblem('?v=2&seed=3')).toMatch(/Unsupported link version "2"/);
    expect(fatalQueryProblem(`?v=1&x=${'a'.repeat(5000)}`)).toMatch(/too long/);
  });
});

describe('Open in Sylva', () => {
  it('drops only the embed keys', () => {
    expect(appQuery('?v=1&seed=7&autorotate=1&bg=transparent&vol=1%3Bs')).toBe(
      'v=1&seed=7&vol=1%3Bs',
    );
    expect(appQuery('')).toBe('');
  });

  it('points at index.html next to the embed page', () => {
    expect(openInSylvaUrl('https://x.org/trees/embed.html?v=1&seed=7', '?v=1&seed=7&bg=red')).toBe(
      'https://x.org/trees/index.html?v=1&seed=7',
    );
    expect(openInSylvaUrl('https://x.org/embed.html', '')).toBe('https://x.org/index.html');
  });
});

describe('snippets', () => {
  const params = { ...defaultParams(registry), seed: 7, levels: 2 };
  const input: SnippetInput = {
    registry,
    params,
    volumes: '',
    edits: '',
    appHref: 'https://example.org/sylva/index.html?v=1&seed=7&levels=2',
    autorotate: true,
    background: 'transparent',
    width: 480,
    height: 360,
  };

  it('embed URL: absolute, next to the app, decodes back to the same params', () => {
    const url = new URL(embedUrl(input));
    expect(url.origin + url.pathname).toBe('https://example.org/sylva/embed.html');
    expect(url.searchParams.get('autorotate')).toBe('1');
    expect(url.searchParams.get('bg')).toBe('transparent');
    expect(decodeQuery(registry, url.search).params).toEqual(params);
    expect(parseEmbedOptions(url.search)).toMatchObject({ autorotate: true, messages: [] });
  });

  it('iframe snippet carries the escaped embed URL and the size', () => {
    const html = iframeSnippet(input);
    expect(html).toMatch(/^<iframe src="https:\/\/example\.org\/sylva\/embed\.html\?v=1&amp;/);
    expect(html).toContain('width="480" height="360"');
    expect(html).toContain('seed=7');
    expect(html).not.toMatch(/&(?!amp;)/);
  });

  it('element snippet: script next to the app, seed and params attributes', () => {
    const html = elementSnippet({ ...input, autorotate: false, background: '#112233' });
    expect(html).toContain(
      '<script type="module" src="https://example.org/sylva/sylva-tree.js"></script>',
    );
    expect(html).toContain('seed="7"');
    expect(html).toContain('params="levels=2"');
    expect(html).toContain('background="#112233"');
    expect(html).not.toContain('autorotate');
  });

  it('both snippets carry the hand edits (e=) as the share link does', () => {
    const edits = '1~c80.410.-20';
    const url = new URL(embedUrl({ ...input, edits }));
    expect(url.searchParams.get('e')).toBe(edits);
    const element = elementSnippet({ ...input, edits });
    expect(element).toContain(`params="levels=2&amp;e=${encodeURIComponent(edits)}"`);
    expect(new URL(embedUrl(input)).searchParams.get('e')).toBeNull();
  });

  it('escapes attribute text', () => {
    expect(escapeAttribute('a"b<c>&d')).toBe('a&quot;b&lt;c&gt;&amp;d');
  });
});
