// Size rule (issue #18): no source file over 500 lines and no function over 120 lines, so every
// file and function can be read whole. `node scripts/sizes.mjs [dir ...]` lists the offenders
// (default: core-rs, web/src and packages/sylva-trees/src) and exits 1 when there is one;
// sizes.test.mjs enforces it.
//
// What counts: Rust sources under core-rs/*/src, TypeScript under web/src and the package's src.
// Tests (a `tests.rs` module file, `*.test.ts(x)`, `*.bench.ts`, anything under a tests/ or
// testing/ folder), generated files (the package's src/wasm, a file marked `@generated` or "do not
// edit" in its first five lines) are left out.
// A function runs from the line of its `fn` / `function` / method name / arrow `=>` to its
// closing brace; nested functions are measured on their own as well as inside their parent.
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

export const MAX_FILE_LINES = 500;
export const MAX_FUNCTION_LINES = 120;

const root = fileURLToPath(new URL('..', import.meta.url));

/**
 * Offenders the rule tolerates for now, as `path` (the file) or `path fn name`. Each is owned by
 * a branch in flight that rewrites it (issue #18 leaves them to their owners); the lead removes
 * the line when that branch lands.
 */
export const ALLOWED = [];

/** True for the files the rule leaves out: tests, benches, generated code. */
export function isExempt(path, text = '') {
  const p = path.replaceAll('\\', '/');
  const inSrc = p.slice(p.indexOf('src/') + 4);
  if (/(^|\/)(tests|testing|wasm)\//.test(inSrc)) return true;
  if (/(^|\/)tests\.rs$/.test(p) || /\.(test|bench)\.tsx?$/.test(p)) return true;
  return /@generated|\bdo not edit\b/i.test(text.split('\n', 5).join('\n'));
}

/** The source files under `dir` (relative to the repo root) that the rule applies to. */
export function sourceFiles(dir) {
  const out = [];
  const walk = (d) => {
    for (const name of readdirSync(d).sort()) {
      const path = join(d, name);
      if (statSync(path).isDirectory()) {
        if (name !== 'node_modules' && name !== 'target') walk(path);
      } else if (/\.(rs|tsx?)$/.test(name) && !/\.d\.ts$/.test(name)) {
        out.push(path);
      }
    }
  };
  walk(join(root, dir));
  return out
    .map((p) => relative(root, p))
    .filter((p) => !isExempt(p, readFileSync(join(root, p), 'utf8')));
}

/** The Rust crates' source folders: core-rs/<crate>/src. */
export function rustSourceDirs() {
  return readdirSync(join(root, 'core-rs'))
    .filter((c) =>
      statSync(join(root, 'core-rs', c, 'src'), { throwIfNoEntry: false })?.isDirectory(),
    )
    .map((c) => `core-rs/${c}/src`);
}

/**
 * `text` with every comment, string and character literal blanked to spaces (line breaks kept),
 * so braces can be counted. `lang` is 'rs' or 'ts'. Rust lifetimes (`'a`) are not literals; in
 * TypeScript a quote right after a letter (JSX text such as `don't`) starts no string.
 */
export function blank(text, lang) {
  const out = [...text];
  const wipe = (from, to) => {
    for (let k = from; k < to; k++) if (out[k] !== '\n') out[k] = ' ';
  };
  let i = 0;
  const n = text.length;
  // TypeScript template literals nest: `${` opens code, whose `}` returns to the template.
  const templates = [];
  let depth = 0;
  while (i < n) {
    const c = text[i];
    const next = text[i + 1];
    if (c === '/' && next === '/') {
      const end = text.indexOf('\n', i);
      const stop = end < 0 ? n : end;
      wipe(i, stop);
      i = stop;
    } else if (c === '/' && next === '*') {
      let level = 1;
      let k = i + 2;
      while (k < n && level > 0) {
        if (lang === 'rs' && text[k] === '/' && text[k + 1] === '*') (level++, (k += 2));
        else if (text[k] === '*' && text[k + 1] === '/') (level--, (k += 2));
        else k++;
      }
      wipe(i, k);
      i = k;
    } else if (lang === 'rs' && /[rb]/.test(c) && /^(b?r#*"|b")/.test(text.slice(i, i + 260))) {
      const m = /^b?r(#*)"/.exec(text.slice(i, i + 260));
      const close = m ? `"${m[1]}` : '"';
      let k = i + (m ? m[0].length : 2);
      if (m) k = text.indexOf(close, k) + close.length;
      else k = skipQuoted(text, k, '"');
      wipe(i, k);
      i = k;
    } else if (
      c === '"' ||
      (lang === 'ts' && c === "'" && !/[\p{L}\p{N}_]/u.test(text[i - 1] ?? ''))
    ) {
      const k = skipQuoted(text, i + 1, c);
      wipe(i, k);
      i = k;
    } else if (lang === 'rs' && c === "'") {
      // A char literal ('x', '\n', '\u{1F600}', '{'), or a lifetime / label ('a, 'static).
      const m = /^'(\\(u\{[0-9a-fA-F]+\}|x[0-9a-fA-F]{2}|.)|[^\\'\n])'/u.exec(
        text.slice(i, i + 12),
      );
      const k = m ? i + m[0].length : i + 1;
      wipe(i, k);
      i = k;
    } else if (lang === 'ts' && c === '`') {
      templates.push(depth);
      i = templateText(text, i + 1, wipe);
      if (text[i - 1] === '`') templates.pop();
    } else if (lang === 'ts' && c === '}' && templates.length && templates.at(-1) === depth) {
      i = templateText(text, i + 1, wipe);
      if (text[i - 1] === '`') templates.pop();
    } else {
      if (c === '{') depth++;
      else if (c === '}') depth--;
      i++;
    }
  }
  return out.join('');
}

function skipQuoted(text, k, quote) {
  while (k < text.length && text[k] !== quote) k += text[k] === '\\' ? 2 : 1;
  return k + 1;
}

/** Blanks template text from `k` to its closing backtick or `${`; returns the index after it. */
function templateText(text, k, wipe) {
  const start = k;
  while (k < text.length) {
    if (text[k] === '\\') k += 2;
    else if (text[k] === '`') return (wipe(start, k), k + 1);
    else if (text[k] === '$' && text[k + 1] === '{') return (wipe(start, k), k + 2);
    else k++;
  }
  wipe(start, k);
  return k;
}

const RUST_FN =
  /^\s*(?:pub(?:\([^)]*\))?\s+)?(?:(?:const|async|unsafe|extern\s+"\w+")\s+)*fn\s+(\w+)/;
const TS_FUNCTION = /\bfunction\b\s*\*?\s*([\w$]*)\s*[<(]/;
const TS_METHOD =
  /^\s*(?:(?:public|private|protected|static|async|override|readonly|get|set)\s+)*([\w$]+)\s*(?:<[^>]*>)?\(.*\)\s*(?::\s*[^{=]+)?\{\s*$/;
const TS_ARROW = /(?:const|let|var)\s+([\w$]+)|([\w$]+)\s*[:=]\s*(?:async\s*)?(?:<[^>]*>)?\(|=>/;
const KEYWORDS = new Set(['if', 'for', 'while', 'switch', 'catch', 'with', 'return', 'function']);

/**
 * The functions of one source file: `{name, start, end, lines}` (1-based lines). `lang` is 'rs'
 * or 'ts'.
 */
export function functions(text, lang) {
  const code = blank(text, lang);
  const lines = code.split('\n');
  // Line starts, to turn offsets into line numbers.
  const starts = [0];
  for (let k = 0; k < code.length; k++) if (code[k] === '\n') starts.push(k + 1);
  const lineOf = (offset) => {
    let lo = 0;
    let hi = starts.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (starts[mid] <= offset) lo = mid;
      else hi = mid - 1;
    }
    return lo;
  };
  // Where each `{` closes.
  const close = new Map();
  const stack = [];
  for (let k = 0; k < code.length; k++) {
    if (code[k] === '{') stack.push(k);
    else if (code[k] === '}' && stack.length) close.set(stack.pop(), k);
  }
  const found = [];
  for (let l = 0; l < lines.length; l++) {
    const line = lines[l];
    let name = null;
    let from = starts[l];
    if (lang === 'rs') {
      const m = RUST_FN.exec(line);
      if (m) name = m[1];
    } else {
      const f = TS_FUNCTION.exec(line);
      const m = TS_METHOD.exec(line);
      if (f) {
        name = f[1] || '(function)';
        from += f.index;
      } else if (m && !KEYWORDS.has(m[1])) {
        name = m[1];
      } else {
        const arrow = line.indexOf('=>');
        if (arrow >= 0 && /^\s*(\{|$)/.test(line.slice(arrow + 2))) {
          const a = TS_ARROW.exec(line);
          name = (a && (a[1] || a[2])) || '(arrow)';
          from += arrow;
        }
      }
    }
    if (name === null) continue;
    // The body: the first `{` after the name, unless a `;` ends a declaration first (Rust).
    let k = from;
    while (k < code.length && code[k] !== '{' && !(lang === 'rs' && code[k] === ';')) k++;
    if (code[k] !== '{' || !close.has(k)) continue;
    const end = lineOf(close.get(k)) + 1;
    found.push({ name, start: l + 1, end, lines: end - l });
  }
  return found;
}

/** Every file and function under `dirs` over the limits: `{path, line, what, lines}`. */
export function offenders(dirs) {
  const out = [];
  for (const dir of dirs) {
    for (const path of sourceFiles(dir)) {
      const text = readFileSync(join(root, path), 'utf8');
      const count = text.endsWith('\n') ? text.split('\n').length - 1 : text.split('\n').length;
      if (count > MAX_FILE_LINES) out.push({ path, line: 1, what: 'file', lines: count });
      const lang = path.endsWith('.rs') ? 'rs' : 'ts';
      for (const f of functions(text, lang))
        if (f.lines > MAX_FUNCTION_LINES)
          out.push({ path, line: f.start, what: `fn ${f.name}`, lines: f.lines });
    }
  }
  return out;
}

/** The key an offender has in `ALLOWED`. */
export const key = (o) => (o.what === 'file' ? o.path : `${o.path} ${o.what}`);

/** One line per offender, as `path:line  what  N lines (limit M)`. */
export function describe(list) {
  return list.map(
    (o) =>
      `${o.path}:${o.line}  ${o.what}  ${o.lines} lines (limit ${o.what === 'file' ? MAX_FILE_LINES : MAX_FUNCTION_LINES})`,
  );
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const dirs =
    process.argv.length > 2
      ? process.argv.slice(2)
      : [...rustSourceDirs(), 'web/src', 'packages/sylva-trees/src'];
  const all = offenders(dirs);
  const list = all.filter((o) => !ALLOWED.includes(key(o)));
  for (const line of describe(list)) console.log(line);
  const allowed = all.length - list.length;
  if (allowed) console.log(`(${allowed} allowed for now: see ALLOWED in scripts/sizes.mjs)`);
  console.log(list.length ? `${list.length} over the limits` : `sizes ok: ${dirs.join(', ')}`);
  process.exitCode = list.length ? 1 : 0;
}
