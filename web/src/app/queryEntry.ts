/**
 * Rewriting one entry of the page query: `key=` replaced by `key=<text>` (or removed when `text`
 * is empty). Every other entry is kept byte for byte: re-serialising the query
 * (URLSearchParams) would re-encode a hostile entry such as `%ZZ` into a valid `%25ZZ`, and the
 * link's own notices would be lost if the app read the URL after that.
 */

/** `search` with its `key` entry set to `text` (removed when empty), the rest as it was. */
export function withQueryEntry(search: string, key: string, text: string): string {
  const pieces = search
    .replace(/^\?/, '')
    .split('&')
    .filter((piece) => piece !== '' && piece.split('=', 1)[0] !== key);
  if (text) pieces.push(`${key}=${encodeURIComponent(text)}`);
  return pieces.length > 0 ? `?${pieces.join('&')}` : '';
}
