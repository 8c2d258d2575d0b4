/**
 * Hostile share links and what the app must make of each: a notice in the banner or silence, and
 * the tree of an equivalent clean link. Shared by the codec's Vitest (every case, through the
 * same load path as the app) and the e2e test (the cases marked `browser`, opened in Chromium:
 * the banner's text, no script run, no CSP violation, the same tree hash).
 */
/** One hostile share link and what the app must make of it. */
export interface HostileCase {
  name: string;
  query: string;
  /** A notice the banner must show, or null when the junk is silently ignored. */
  notice: RegExp | null;
  /** The clean query that gives the same tree. */
  same: string;
  /** Also opened in the browser by the e2e test (the rest only go through the codec). */
  browser?: boolean;
}

/** The default tree's query. */
export const DEFAULT = '?v=1';
/** The tree of seed 5. */
export const SEED5 = '?v=1&seed=5';
const bad = (key: string): RegExp => new RegExp(`Ignored "${key}" from the link`);

/** A link whose bad `key` is reported and ignored: the default tree. */
const ignored = (name: string, query: string, key: string): HostileCase => ({
  name,
  query,
  notice: bad(key),
  same: DEFAULT,
});
/** A link that shows `notice` in the banner and draws the tree of `same`. */
const noticed = (name: string, query: string, notice: RegExp, same = DEFAULT): HostileCase => ({
  name,
  query,
  notice,
  same,
});
/** A link whose junk is dropped without a notice: the tree of `same`. */
const silent = (name: string, query: string, same: string): HostileCase => ({
  name,
  query,
  notice: null,
  same,
});

/** A case the e2e test also opens in a fresh page. */
const inBrowser = (c: HostileCase): HostileCase => ({ ...c, browser: true });

/** The notice of a dropped `e=` list, with what must be named in it. */
const droppedEdits = (why: string): RegExp =>
  new RegExp(`^Ignored the edits in the link: .*${why}.*Import edits…`);

/**
 * Hostile hand edits (`e=`): the whole list is dropped with one notice naming what was wrong,
 * and the tree is the one without edits. (A good `e=` list is never part of `same` here, so
 * the browser cases hold for any core.)
 */
const HOSTILE_EDITS: HostileCase[] = [
  inBrowser(
    noticed('edits: NaN', '?v=1&seed=5&e=1~cNaN.410.0', droppedEdits('e\\[0\\]: "NaN"'), SEED5),
  ),
  inBrowser(
    noticed(
      'edits: huge number',
      '?v=1&seed=5&e=1~c9999999.410.0',
      droppedEdits('edits\\[0\\]\\.at\\[0\\] is 99999.99'),
      SEED5,
    ),
  ),
  noticed('edits: exponent', '?v=1&e=1~c1e9.410.0', droppedEdits('"1e9" is not a whole number')),
  noticed('edits: too many digits', '?v=1&e=1~c12345678.410.0', droppedEdits('not a whole number')),
  inBrowser(
    noticed(
      'edits: unknown op',
      '?v=1&seed=5&e=1~c80.410.-20~z1.2.3',
      droppedEdits('e\\[1\\]: unknown op "z"'),
      SEED5,
    ),
  ),
  noticed('edits: wrong version', '?v=1&e=9~c80.410.-20', droppedEdits('unsupported version "9"')),
  inBrowser(
    noticed(
      'edits: script garbage',
      `?v=1&seed=5&e=${encodeURIComponent('<script>window.__xss=1</script>')}`,
      droppedEdits('unsupported version'),
      SEED5,
    ),
  ),
  noticed(
    'edits: wrong count',
    '?v=1&e=1~b200.550.0.230',
    droppedEdits('a bend takes 6 numbers, got 4'),
  ),
  noticed(
    'edits: cut on the ground',
    '?v=1&e=1~c80.2.0',
    droppedEdits('edits\\[0\\]\\.at is on the ground'),
  ),
  noticed(
    'edits: brush of 0',
    '?v=1&e=1~p0.400.25.40.0.300.0',
    droppedEdits('edits\\[0\\]\\.radius is 0'),
  ),
  noticed(
    'edits: brush of 1 km',
    '?v=1&e=1~p100000.400.25.40.0.300.0',
    droppedEdits('edits\\[0\\]\\.radius is 1000'),
  ),
  noticed(
    'edits: outline crossing itself',
    '?v=1&e=1~o0.0.200.200.0.-200.-200.200',
    droppedEdits('crosses itself'),
  ),
  inBrowser(
    noticed(
      'edits: too many points (long)',
      `?v=1&seed=5&e=1~p60.400.25.40.0.300.0${'.0.0.1'.repeat(5000)}`,
      droppedEdits('too long'),
      SEED5,
    ),
  ),
  noticed(
    'edits: thousands of edits',
    `?v=1&e=1${'~c1.100.1'.repeat(3000)}`,
    droppedEdits('too long'),
  ),
  noticed('edits: empty item', '?v=1&e=1~~c80.410.-20', droppedEdits('e\\[0\\]')),
];

/** Eight bad values at once: the banner lists six and counts the rest. */
export const EIGHT_BAD = [
  'scale',
  'seed',
  'levels',
  'ratio',
  'l1_length',
  'l2_length',
  'flare',
  'lobes',
]
  .map((k) => `${k}=x`)
  .join('&');

/** Every hostile link of the table (at least 30). */
export const HOSTILE: HostileCase[] = [
  ignored('huge number', '?v=1&scale=1e308', 'scale'),
  ignored('huge negative', '?v=1&scale=-1e308', 'scale'),
  inBrowser(ignored('overflow to Infinity', '?v=1&scale=1e999', 'scale')),
  ignored('underflow to 0', '?v=1&scale=1e-400', 'scale'),
  ignored('NaN', '?v=1&l1_length=NaN', 'l1_length'),
  ignored('Infinity', '?v=1&l1_length=Infinity', 'l1_length'),
  ignored('-Infinity', '?v=1&l1_length=-Infinity', 'l1_length'),
  ignored('negative count', '?v=1&l1_branches=-5', 'l1_branches'),
  ignored('fractional count', '?v=1&l1_branches=2.5', 'l1_branches'),
  ignored('levels 0', '?v=1&levels=0', 'levels'),
  ignored('20-digit levels', '?v=1&levels=99999999999999999999', 'levels'),
  ignored('enum out of range', '?v=1&shape=9', 'shape'),
  ignored('bool 2', '?v=1&show_preview=2', 'show_preview'),
  ignored('budget 1e12', '?v=1&max_vertices=1e12', 'max_vertices'),
  ignored('hex', '?v=1&seed=0x10', 'seed'),
  inBrowser(noticed('unknown version', '?v=999&seed=5', /version "999"/)),
  noticed('version 0', '?v=0&seed=5', /version "0"/),
  noticed('version 1.0', '?v=1.0&seed=5', /version "1\.0"/),
  inBrowser(noticed('emoji version', '?v=%F0%9F%8C%B3&seed=5', /version/)),
  inBrowser(
    ignored(
      'script value',
      `?v=1&seed=${encodeURIComponent('<script>window.__xss=1</script>')}`,
      'seed',
    ),
  ),
  inBrowser(
    ignored(
      'img onerror value',
      `?v=1&scale=${encodeURIComponent('"><img src=x onerror="window.__xss=1">')}`,
      'scale',
    ),
  ),
  inBrowser(
    ignored(
      'javascript: value',
      `?v=1&seed=${encodeURIComponent('javascript:window.__xss=1')}`,
      'seed',
    ),
  ),
  inBrowser(
    silent(
      'script key',
      `?v=1&${encodeURIComponent('<script>window.__xss=1</script>')}=1&seed=5`,
      SEED5,
    ),
  ),
  inBrowser(ignored('statement injection', '?v=1&seed=5;window.__xss=1', 'seed')),
  inBrowser(noticed('100 kB value', `?v=1&seed=${'9'.repeat(100_000)}`, /too long/)),
  ignored('lone %', '?v=1&seed=%', 'seed'),
  ignored('truncated UTF-8', '?v=1&seed=%E0%A4%A', 'seed'),
  ignored('encoded surrogate', '?v=1&seed=%ED%A0%80', 'seed'),
  inBrowser(noticed('broken key encoding', '?v=1&%ZZ=1&seed=5', /malformed/, SEED5)),
  inBrowser(noticed('duplicated key', '?v=1&seed=5&seed=6', /repeated "seed"/, SEED5)),
  silent('empty key', '?v=1&=5&seed=5', SEED5),
  silent('stray separators', '?&&v=1&&&seed=5&&', SEED5),
  inBrowser(
    silent('prototype keys', '?v=1&__proto__=1&constructor=2&__proto__%5Bx%5D=3&seed=5', SEED5),
  ),
  silent('wrong-case key', '?v=1&SEED=5', DEFAULT),
  ignored('full-width digit', '?v=1&seed=%EF%BC%95', 'seed'),
  ignored('Arabic-Indic digit', '?v=1&seed=%D9%A5', 'seed'),
  ignored('null byte after', '?v=1&seed=5%00', 'seed'),
  ignored('null byte alone', '?v=1&seed=%00', 'seed'),
  inBrowser(ignored('bidi override', '?v=1&seed=%E2%80%AE5', 'seed')),
  ignored('leading space (+)', '?v=1&seed=+5', 'seed'),
  inBrowser(silent('hostile debug flag', '?v=1&seed=5&debug=%3Cscript%3E', SEED5)),
  inBrowser(silent('junk fragment', '?v=1&seed=5#%3Cscript%3Ewindow.__xss=1', SEED5)),
  silent(
    '300 unknown keys',
    `?v=1&${Array.from({ length: 300 }, (_, i) => `k${i}=${i}`).join('&')}&seed=5`,
    SEED5,
  ),
  inBrowser(noticed('many bad values (capped)', `?v=1&${EIGHT_BAD}`, /…and 2 more problems/)),
  ...HOSTILE_EDITS,
];
