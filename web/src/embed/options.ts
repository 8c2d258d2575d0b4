/**
 * Embedding, pure logic: the embed page's own query options (`autorotate`, `bg`), the query the
 * "Open in Sylva" link carries, and the iframe / `<sylva-tree>` snippets of "Copy embed code".
 */
import { Color } from 'three';
import {
  EDITS_KEY,
  encodeParams,
  FORMAT_VERSION,
  MAX_QUERY_LENGTH,
  shown,
  VOLUMES_KEY,
} from 'sylva-trees/url';
import type { Params, ParamSpec } from 'sylva-trees/core';

/** How the viewer background is drawn. */
export type Background =
  | { kind: 'default' }
  | { kind: 'transparent' }
  /** A `#rrggbb` colour (named and short colours are normalised to it). */
  | { kind: 'color'; color: string };

/** The embed page's own options, read from its query next to the share-link params. */
export interface EmbedOptions {
  autorotate: boolean;
  /** Wind animation (`wind=0` turns it off; on by default). */
  wind: boolean;
  background: Background;
  /** Problems with these options (the option falls back to its default). */
  messages: string[];
}

/** Query keys of the embed page that are not tree parameters (dropped from "Open in Sylva"). */
export const EMBED_KEYS: readonly string[] = ['autorotate', 'bg', 'wind'];

const HEX_RE = /^#([0-9a-f]{3}|[0-9a-f]{6})$/i;

/**
 * Parses a background option: `transparent`, `#rgb` / `#rrggbb`, or a CSS colour name; anything
 * else is an error string. The colour never reaches CSS or HTML as text: it becomes `#rrggbb`.
 */
export function parseBackground(raw: string | null): Background | string {
  if (raw === null || raw === '') return { kind: 'default' };
  const text = raw.trim().toLowerCase();
  if (text === 'transparent' || text === 'none') return { kind: 'transparent' };
  if (HEX_RE.test(text)) {
    return { kind: 'color', color: `#${new Color(text).getHexString()}` };
  }
  const names = Color.NAMES as Record<string, number>;
  if (/^[a-z]{3,24}$/.test(text) && Object.hasOwn(names, text)) {
    const value = names[text] ?? 0;
    return { kind: 'color', color: `#${value.toString(16).padStart(6, '0')}` };
  }
  return `"${shown(raw)}" is not a colour (use transparent, #rrggbb or a CSS colour name)`;
}

/** Reads a yes/no option: 1/true/yes/on or empty (present) → true, 0/false/no/off → false. */
export function parseFlag(raw: string | null): boolean | null {
  if (raw === null) return false;
  const text = raw.trim().toLowerCase();
  if (['', '1', 'true', 'yes', 'on', 'autorotate'].includes(text)) return true;
  if (['0', 'false', 'no', 'off'].includes(text)) return false;
  return null;
}

/** Raw value of the first `key` in a query (`null` if absent or badly %-encoded). */
function firstValue(query: string, key: string): string | null {
  for (const piece of query.split('&')) {
    const eq = piece.indexOf('=');
    const rawKey = eq < 0 ? piece : piece.slice(0, eq);
    if (rawKey !== key) continue;
    try {
      return decodeURIComponent((eq < 0 ? '' : piece.slice(eq + 1)).replace(/\+/g, ' '));
    } catch {
      return null;
    }
  }
  return null;
}

function stripQuestion(search: string): string {
  return search.startsWith('?') ? search.slice(1) : search;
}

/** The embed page options from its query (with or without the leading `?`). Never throws. */
export function parseEmbedOptions(search: string): EmbedOptions {
  const query = stripQuestion(search).slice(0, MAX_QUERY_LENGTH);
  const messages: string[] = [];
  const flag = parseFlag(firstValue(query, 'autorotate'));
  if (flag === null) {
    messages.push(`Ignored "autorotate": use autorotate=1 or autorotate=0.`);
  }
  const windRaw = firstValue(query, 'wind');
  const wind = windRaw === null ? true : parseFlag(windRaw);
  if (wind === null) messages.push(`Ignored "wind": use wind=1 or wind=0.`);
  const bg = parseBackground(firstValue(query, 'bg'));
  if (typeof bg === 'string') messages.push(`Ignored "bg": ${bg}.`);
  return {
    autorotate: flag ?? false,
    wind: wind ?? true,
    background: typeof bg === 'string' ? { kind: 'default' } : bg,
    messages,
  };
}

/**
 * Whether a share query cannot give a meaningful tree at all: over-long, or a version this app
 * does not read (the codec would fall back to the defaults; an embed shows an error instead).
 * Returns the reason, or null when the query is usable.
 */
export function fatalQueryProblem(search: string): string | null {
  const query = stripQuestion(search);
  if (query.length > MAX_QUERY_LENGTH) {
    return `The link is too long (${query.length} characters, limit ${MAX_QUERY_LENGTH}).`;
  }
  const version = query.split('&').find((p) => p === 'v' || p.startsWith('v='));
  if (version !== undefined && version !== `v=${FORMAT_VERSION}`) {
    const value = version.slice(2);
    return `Unsupported link version "${shown(value)}" (this Sylva reads v=${FORMAT_VERSION}).`;
  }
  return null;
}

/** The share query without the embed-only keys (what "Open in Sylva" opens in the app). */
export function appQuery(search: string): string {
  return stripQuestion(search)
    .split('&')
    .filter((piece) => {
      if (piece === '') return false;
      const eq = piece.indexOf('=');
      const key = eq < 0 ? piece : piece.slice(0, eq);
      return !EMBED_KEYS.includes(key);
    })
    .join('&');
}

/** `index.html?<query>` for the "Open in Sylva" link, resolved against the embed page URL. */
export function openInSylvaUrl(embedHref: string, search: string): string {
  const query = appQuery(search);
  const url = new URL('index.html', embedHref);
  return query === '' ? url.href : `${url.href}?${query}`;
}

/** What a snippet embeds: the current tree plus the viewer options. */
export interface SnippetInput {
  registry: readonly ParamSpec[];
  params: Params;
  /** The `vol=` value of the growth volumes ('' when none). */
  volumes: string;
  /** The `e=` value of the hand edits ('' when none, or too long for a link). */
  edits: string;
  /** The page the app runs at (`location.href`): the embed URLs are resolved against it. */
  appHref: string;
  autorotate: boolean;
  /** `transparent`, a colour, or '' for the default sky. */
  background: string;
  width: number;
  height: number;
}

/** Escapes text for a double-quoted HTML attribute value. */
export function escapeAttribute(text: string): string {
  return text
    .replace(/&/g, '&amp;')
    .replace(/"/g, '&quot;')
    .replace(/</g, '&lt;')
    .replace(/>/g, '&gt;');
}

/** The absolute embed page URL for the current tree and options. */
export function embedUrl(input: SnippetInput): string {
  const parts = [encodeParams(input.registry, input.params)];
  if (input.volumes !== '') parts.push(`${VOLUMES_KEY}=${encodeURIComponent(input.volumes)}`);
  if (input.edits !== '') parts.push(`${EDITS_KEY}=${encodeURIComponent(input.edits)}`);
  if (input.autorotate) parts.push('autorotate=1');
  if (input.background !== '') parts.push(`bg=${encodeURIComponent(input.background)}`);
  return `${new URL('embed.html', input.appHref).href}?${parts.join('&')}`;
}

/** `<iframe src=".../embed.html?...">` for the current tree. */
export function iframeSnippet(input: SnippetInput): string {
  const src = escapeAttribute(embedUrl(input));
  return (
    `<iframe src="${src}" width="${input.width}" height="${input.height}" ` +
    `title="Sylva tree" loading="lazy" style="border:0"></iframe>`
  );
}

/**
 * The `<sylva-tree>` snippet: the script tag (absolute URL next to the app) and the element with
 * `seed` and the other non-default values in `params`.
 */
export function elementSnippet(input: SnippetInput): string {
  const script = new URL('sylva-tree.js', input.appHref).href;
  const seedSpec = input.registry.find((s) => s.id === 'seed');
  const rest = input.registry.filter((s) => s !== seedSpec);
  const query = encodeParams(rest, input.params)
    .split('&')
    .filter((p) => !p.startsWith('v='));
  if (input.volumes !== '') query.push(`${VOLUMES_KEY}=${encodeURIComponent(input.volumes)}`);
  if (input.edits !== '') query.push(`${EDITS_KEY}=${encodeURIComponent(input.edits)}`);
  const attrs: string[] = [];
  if (seedSpec) attrs.push(`seed="${input.params[seedSpec.id] ?? seedSpec.default}"`);
  if (query.length > 0) attrs.push(`params="${escapeAttribute(query.join('&'))}"`);
  if (input.autorotate) attrs.push('autorotate');
  if (input.background !== '') attrs.push(`background="${escapeAttribute(input.background)}"`);
  attrs.push(`style="display:block;width:${input.width}px;height:${input.height}px"`);
  return (
    `<script type="module" src="${escapeAttribute(script)}"></script>\n` +
    `<sylva-tree ${attrs.join(' ')}></sylva-tree>`
  );
}
