/**
 * The Content-Security-Policy of the app, kept in `index.html` as a `<meta http-equiv>` so that
 * any static host of `web/dist/` serves it. Helpers here parse it (tests) and add a nonce for
 * the Vite dev server, whose inline React Refresh preamble and injected `<style>` tags need one.
 */

/** Directive name → its source list, in order. */
export type Policy = Map<string, string[]>;

/** Parses a policy string (`name src src; name src`); directive names are lower-cased. */
export function parsePolicy(text: string): Policy {
  const policy: Policy = new Map();
  for (const part of text.split(';')) {
    const [name, ...sources] = part.trim().split(/\s+/);
    if (name) policy.set(name.toLowerCase(), sources);
  }
  return policy;
}

/** Serialises a policy back to `name src src; ...`. */
export function formatPolicy(policy: Policy): string {
  return [...policy].map(([name, sources]) => [name, ...sources].join(' ')).join('; ');
}

const META_RE = /(<meta\s+http-equiv="Content-Security-Policy"\s+content=")([^"]*)(")/i;

/** The policy text of the CSP `<meta>` in an HTML document, or null. */
export function policyOfHtml(html: string): string | null {
  return META_RE.exec(html)?.[2] ?? null;
}

/**
 * Adds `'nonce-…'` to `script-src` and `style-src` of the CSP `<meta>` (dev server only: the
 * built site needs no inline script or style). Throws if the page has no CSP `<meta>`, so the
 * policy cannot silently disappear.
 */
export function withNonce(html: string, nonce: string): string {
  if (!/^[A-Za-z0-9+/=_-]+$/.test(nonce)) throw new Error('bad nonce');
  const text = policyOfHtml(html);
  if (text === null) throw new Error('index.html has no Content-Security-Policy meta tag');
  const policy = parsePolicy(text);
  for (const name of ['script-src', 'style-src']) {
    const sources = policy.get(name) ?? [...(policy.get('default-src') ?? [])];
    policy.set(name, [...sources, `'nonce-${nonce}'`]);
  }
  return html.replace(META_RE, (_all, start: string, _old: string, end: string) => {
    return `${start}${formatPolicy(policy)}${end}`;
  });
}
