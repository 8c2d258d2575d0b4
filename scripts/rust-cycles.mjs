// No import cycles between the files of a Rust crate. `node scripts/rust-cycles.mjs [crate-dir ...]`
// (default: every core-rs/<crate> with a src/ folder) prints each cycle as a chain of files and
// exits 1 when there is one; scripts/lint.sh runs it.
//
// The graph: one node per source file under <crate>/src. A file's module path comes from where it
// sits (src/lib.rs or src/main.rs is the crate root, src/a/mod.rs and src/a.rs are `a`,
// src/a/b.rs is `a::b`); `mod name { ... }` blocks inside a file are modules of that file.
// An edge A -> B means code in file A names module B or an item of it, through:
// * a `use` tree (`pub use` included: a re-export is an edge of the file that holds it), whose
//   path starts with `crate`, `self`, `super` or a module name in scope;
// * a path in code of two segments or more that starts with `crate::`, `self::`, `super::` or
//   a module name in scope (`crate::mesh::tube::Frame`, `super::Hole`, `tube::build(..)`).
// A module name in scope is a child module of the module the code is in (declared with `mod`),
// or a name a `use` in the same file binds to a module (`use crate::mesh::tube;`).
// A path resolves to the file of its longest prefix that is a module: `crate::mesh::tube::Frame`
// goes to mesh/tube/mod.rs, `crate::TreeMesh` to lib.rs even when lib.rs re-exports it (then
// lib.rs's `pub use` is the next edge). `self`, `super` and `crate` follow the module tree.
// Not edges: `mod name;` declarations (they declare the module tree; the parent does not use
// anything by them), paths into other crates (`std`, `glam`, `sylva_core`, ...), paths in
// comments, doc comments (intra-doc links only build documentation) and string literals, a file
// naming itself, and `$crate` in macros.
// Left out: `#[cfg(test)]` items (unit test modules, inline or in their own file such as
// tests.rs, and test-only helpers). They are compiled only into the crate's test build, are the
// children of the module they test (`use super::*` points back by design) and may borrow
// fixtures from anywhere; no library code depends on them, so they cannot be part of a cycle
// that library code must untangle.
// `#[path = "..."]` module files are not resolved; a crate source using one is reported.
// A cycle is a strongly connected component of two files or more; each is printed as chains
// `a.rs -> b.rs -> a.rs` (a shortest cycle through each of its files not yet shown).
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));

/**
 * The text with comments, string and char literals blanked to spaces (newlines kept), so that
 * offsets and line numbers still match the source.
 */
export function stripCode(text) {
  const out = [...text];
  const blank = (from, to) => {
    for (let k = from; k < to; k++) if (out[k] !== '\n') out[k] = ' ';
  };
  const chars = out.slice();
  let i = 0;
  while (i < chars.length) {
    const c = chars[i];
    const next = chars[i + 1];
    if (c === '/' && next === '/') {
      let j = i;
      while (j < chars.length && chars[j] !== '\n') j++;
      blank(i, j);
      i = j;
    } else if (c === '/' && next === '*') {
      let depth = 0;
      let j = i;
      do {
        if (chars[j] === '/' && chars[j + 1] === '*') (depth++, (j += 2));
        else if (chars[j] === '*' && chars[j + 1] === '/') (depth--, (j += 2));
        else j++;
      } while (depth > 0 && j < chars.length);
      blank(i, j);
      i = j;
    } else if (/[A-Za-z0-9_]/.test(c) && !/[rb]/.test(c)) {
      while (i < chars.length && /[A-Za-z0-9_]/.test(chars[i])) i++;
    } else if ((c === 'r' || (c === 'b' && next === 'r')) && rawStringEnd(chars, i) > 0) {
      const j = rawStringEnd(chars, i);
      blank(i, j);
      i = j;
    } else if (c === '"' || (c === 'b' && next === '"')) {
      let j = c === 'b' ? i + 2 : i + 1;
      while (j < chars.length && chars[j] !== '"') j += chars[j] === '\\' ? 2 : 1;
      blank(i, j + 1);
      i = j + 1;
    } else if (c === "'" || (c === 'b' && next === "'")) {
      const q = c === 'b' ? i + 1 : i;
      const end = charLiteralEnd(chars, q);
      if (end > 0) blank(i, end);
      i = end > 0 ? end : q + 1;
    } else if (/[A-Za-z_]/.test(c)) {
      while (i < chars.length && /[A-Za-z0-9_]/.test(chars[i])) i++;
    } else {
      i++;
    }
  }
  return out.join('');
}

/** End (exclusive) of a raw string `r#"..."#` / `br"..."` starting at `i`, or 0 if none is. */
function rawStringEnd(chars, i) {
  let j = chars[i] === 'b' ? i + 2 : i + 1;
  let hashes = 0;
  while (chars[j] === '#') (hashes++, j++);
  if (chars[j] !== '"') return 0;
  const close = '"' + '#'.repeat(hashes);
  for (j++; j < chars.length; j++) {
    if (chars.slice(j, j + close.length).join('') === close) return j + close.length;
  }
  return chars.length;
}

/** End (exclusive) of a char literal at the quote `q`, or 0 for a lifetime / label. */
function charLiteralEnd(chars, q) {
  if (chars[q + 1] === '\\') {
    let j = q + 2;
    while (j < chars.length && chars[j] !== "'" && chars[j] !== '\n') j++;
    return chars[j] === "'" ? j + 1 : 0;
  }
  return chars[q + 2] === "'" ? q + 3 : 0;
}

/** Blanks every `#[cfg(test)]` item (attribute included) of stripped code; returns the text and the names of `mod name;` declarations among them. */
export function dropTestItems(code) {
  const out = [...code];
  const testMods = [];
  const attr = /#\[cfg\(test\)\]/g;
  let m;
  while ((m = attr.exec(code))) {
    let j = m.index + m[0].length;
    let depth = 0;
    for (; j < code.length; j++) {
      const c = code[j];
      if (c === '(' || c === '[') depth++;
      else if (c === ')' || c === ']') depth--;
      else if (depth === 0 && c === ';') break;
      else if (depth === 0 && c === '{') {
        j = matchingBrace(code, j);
        break;
      }
    }
    const item = code.slice(m.index + m[0].length, j + 1);
    const decl = /^\s*(?:pub(?:\([^)]*\))?\s+)?mod\s+([A-Za-z_]\w*)\s*;$/.exec(item);
    if (decl) testMods.push(decl[1]);
    for (let k = m.index; k <= j && k < out.length; k++) if (out[k] !== '\n') out[k] = ' ';
    attr.lastIndex = j + 1;
  }
  return { code: out.join(''), testMods };
}

function matchingBrace(code, open) {
  let depth = 0;
  for (let j = open; j < code.length; j++) {
    if (code[j] === '{') depth++;
    else if (code[j] === '}' && --depth === 0) return j;
  }
  return code.length - 1;
}

/**
 * The paths a use tree (the text between `use` and `;`) imports: `{ segs, binds }` per leaf, with
 * `binds` the name it brings into scope (null for a glob, whose `segs` name the module).
 */
export function expandUseTree(tree) {
  const text = tree
    .replace(/\s+/g, ' ')
    .replace(/\s*(::|[{},])\s*/g, '$1')
    .trim();
  const out = [];
  const walk = (prefix, s) => {
    const brace = s.indexOf('{');
    if (brace < 0) {
      const [path, alias] = s.split(' as ');
      const segs = [...prefix, ...path.split('::').filter(Boolean)];
      if (segs.at(-1) === 'self') segs.pop();
      if (segs.length === 0) return;
      const glob = segs.at(-1) === '*';
      if (glob) segs.pop();
      out.push({ segs, binds: glob ? null : (alias ?? segs.at(-1)) });
      return;
    }
    const head = s.slice(0, brace).split('::').filter(Boolean);
    for (const part of splitTop(s.slice(brace + 1, s.lastIndexOf('}')))) {
      if (part) walk([...prefix, ...head], part);
    }
  };
  walk([], text);
  return out;
}

/** Splits `a,b::{c,d},e` at its top-level commas. */
function splitTop(s) {
  const parts = [];
  let depth = 0;
  let start = 0;
  for (let k = 0; k < s.length; k++) {
    if (s[k] === '{') depth++;
    else if (s[k] === '}') depth--;
    else if (s[k] === ',' && depth === 0) (parts.push(s.slice(start, k)), (start = k + 1));
  }
  parts.push(s.slice(start));
  return parts;
}

/** The module path of a source file relative to its crate's src/ (`a/b.rs` -> `['a', 'b']`). */
export function modulePathOf(file) {
  const segs = file.replace(/\.rs$/, '').split('/');
  const last = segs.at(-1);
  if (last === 'mod' || (segs.length === 1 && (last === 'lib' || last === 'main'))) segs.pop();
  return segs;
}

/**
 * One crate's file-level module graph. `files` maps a path relative to src/ (`mesh/tube/mod.rs`)
 * to its text; returns `Map<file, Set<file>>` without the `#[cfg(test)]` files, and the files
 * that use `#[path]`.
 */
export function crateGraph(files) {
  const parsed = new Map();
  for (const [file, text] of files) {
    const { code, testMods } = dropTestItems(stripCode(text));
    parsed.set(file, { code, testMods, mod: modulePathOf(file) });
  }
  // Modules: file modules, then inline `mod name {` blocks with their span in the file.
  const modules = new Map(); // 'a::b' -> { file, segs }
  const testFiles = new Set();
  const key = (segs) => segs.join('::');
  for (const [file, p] of parsed) modules.set(key(p.mod), { file, segs: p.mod });
  for (const [file, p] of parsed) {
    for (const name of p.testMods) {
      for (const [k, m] of modules) {
        if (k === key([...p.mod, name]) || k.startsWith(key([...p.mod, name]) + '::')) {
          testFiles.add(m.file);
        }
      }
    }
    p.inline = inlineModules(p.code, p.mod);
    for (const im of p.inline) modules.set(key(im.segs), { file, segs: im.segs });
  }
  const childNames = (segs) => {
    const names = new Set();
    for (const m of modules.values()) {
      if (m.segs.length === segs.length + 1 && key(m.segs.slice(0, -1)) === key(segs)) {
        names.add(m.segs.at(-1));
      }
    }
    return names;
  };
  const fileOf = (abs) => {
    for (let n = abs.length; n >= 0; n--) {
      const m = modules.get(key(abs.slice(0, n)));
      if (m) return m.file;
    }
    return null;
  };
  // `mod name` declared without `pub`: a private child module.
  const privateMods = new Set();
  for (const p of parsed.values()) {
    const declRe = /(?<![\w$])(pub\s*(?:\([^)]*\))?\s*)?mod\s+([A-Za-z_]\w*)\s*[;{]/g;
    for (const m of p.code.matchAll(declRe)) {
      const scope = p.inline.filter((im) => im.start < m.index && m.index < im.end).at(-1);
      if (!m[1]) privateMods.add(key([...(scope ? scope.segs : p.mod), m[2]]));
    }
  }
  // True when `inner` is in the private subtree of `outer`: every module below `outer` down to
  // `inner` is declared without `pub`.
  const privateBelow = (outer, inner) => {
    if (inner.length <= outer.length || key(inner.slice(0, outer.length)) !== key(outer)) {
      return false;
    }
    for (let n = outer.length + 1; n <= inner.length; n++) {
      if (!privateMods.has(key(inner.slice(0, n)))) return false;
    }
    return true;
  };
  const graph = new Map();
  const pathFiles = [];
  for (const [file, p] of parsed) {
    if (testFiles.has(file)) continue;
    if (/#\[path\s*=/.test(p.code)) pathFiles.push(file);
    const deps = new Set();
    const scopeAt = (offset) => {
      let mod = p.mod;
      for (const im of p.inline) if (im.start < offset && offset < im.end) mod = im.segs;
      return mod;
    };
    // Absolute module path of `segs` seen from `mod`, or null for another crate's path.
    const absolute = (segs, mod, aliases) => {
      let [first, ...rest] = segs;
      if (first === 'crate') return rest;
      if (first === 'self') return [...mod, ...rest];
      if (first === 'super') {
        let base = mod.slice(0, -1);
        while (rest[0] === 'super') ((base = base.slice(0, -1)), rest.shift());
        return [...base, ...rest];
      }
      if (childNames(mod).has(first)) return [...mod, first, ...rest];
      if (aliases.has(first)) return [...aliases.get(first), ...rest];
      return null;
    };
    const add = (abs) => {
      const target = abs && fileOf(abs);
      if (!target || target === file || testFiles.has(target)) return;
      const [from, to] = [p.mod, parsed.get(target).mod];
      if (privateBelow(to, from)) return;
      deps.add(target);
    };
    // Use trees first: their leaves that name a module become aliases for the paths in code.
    const aliases = new Map();
    const useRe = /\buse\s+([^;]*);/g;
    let code = p.code;
    for (const m of p.code.matchAll(useRe)) {
      const mod = scopeAt(m.index);
      for (const leaf of expandUseTree(m[1])) {
        const abs = absolute(leaf.segs, mod, new Map());
        add(abs);
        if (abs && leaf.binds && modules.has(key(abs))) aliases.set(leaf.binds, abs);
      }
      code = code.slice(0, m.index) + ' '.repeat(m[0].length) + code.slice(m.index + m[0].length);
    }
    // `pub(in crate::a)` is visibility, not a use.
    code = code.replace(/\bpub\s*\(\s*in\s+[^)]*\)/g, (s) => ' '.repeat(s.length));
    const pathRe = /(?<![\w$:])([A-Za-z_]\w*)((?:\s*::\s*[A-Za-z_]\w*)+)/g;
    for (const m of code.matchAll(pathRe)) {
      const segs = [
        m[1],
        ...m[2]
          .split('::')
          .map((s) => s.trim())
          .filter(Boolean),
      ];
      add(absolute(segs, scopeAt(m.index), aliases));
    }
    graph.set(file, deps);
  }
  return { graph, pathFiles };
}

/** The inline `mod name { ... }` blocks of stripped code, nested ones included, with their spans. */
function inlineModules(code, fileMod) {
  const found = [];
  const re = /\bmod\s+([A-Za-z_]\w*)\s*\{/g;
  for (const m of code.matchAll(re)) {
    const open = m.index + m[0].length - 1;
    found.push({ name: m[1], start: open, end: matchingBrace(code, open) });
  }
  for (const im of found) {
    const parents = found.filter((o) => o.start < im.start && im.end < o.end);
    parents.sort((a, b) => a.start - b.start);
    im.segs = [...fileMod, ...parents.map((o) => o.name), im.name];
  }
  // Innermost last, so a lookup that keeps the last match finds the innermost module.
  return found.sort((a, b) => a.start - b.start);
}

/**
 * The cycles of a graph (`Map<node, Set<node>>`): one list of chains per strongly connected
 * component of two nodes or more, each chain a shortest cycle `[a, b, ..., a]`, together covering
 * every node of the component.
 */
export function findCycles(graph) {
  const components = stronglyConnected(graph).filter((c) => c.length > 1);
  return components.map((component) => {
    const inside = new Set(component);
    const covered = new Set();
    const chains = [];
    for (const start of [...component].sort()) {
      if (covered.has(start)) continue;
      const chain = shortestCycle(graph, start, inside);
      chain.forEach((n) => covered.add(n));
      chains.push(chain);
    }
    return chains;
  });
}

/** Tarjan's strongly connected components, in a deterministic order. */
function stronglyConnected(graph) {
  const index = new Map();
  const low = new Map();
  const stack = [];
  const onStack = new Set();
  const out = [];
  let counter = 0;
  const visit = (v) => {
    index.set(v, counter);
    low.set(v, counter++);
    stack.push(v);
    onStack.add(v);
    for (const w of [...(graph.get(v) ?? [])].sort()) {
      if (!index.has(w)) (visit(w), low.set(v, Math.min(low.get(v), low.get(w))));
      else if (onStack.has(w)) low.set(v, Math.min(low.get(v), index.get(w)));
    }
    if (low.get(v) === index.get(v)) {
      const component = [];
      let w;
      do ((w = stack.pop()), onStack.delete(w), component.push(w));
      while (w !== v);
      out.push(component.sort());
    }
  };
  for (const v of [...graph.keys()].sort()) if (!index.has(v)) visit(v);
  return out.sort((a, b) => (a[0] < b[0] ? -1 : 1));
}

/** A shortest cycle from `start` back to it inside `inside` (breadth-first). */
function shortestCycle(graph, start, inside) {
  const prev = new Map();
  const queue = [start];
  for (let q = 0; q < queue.length; q++) {
    const v = queue[q];
    for (const w of [...(graph.get(v) ?? [])].sort()) {
      if (!inside.has(w)) continue;
      if (w === start) {
        const path = [];
        for (let u = v; u !== start; u = prev.get(u)) path.unshift(u);
        return [start, ...path, start];
      }
      if (!prev.has(w)) (prev.set(w, v), queue.push(w));
    }
  }
  return [start];
}

/** Every .rs file under `dir`, relative to it, with `/` separators. */
function rustFiles(dir) {
  const out = new Map();
  const walk = (d) => {
    for (const name of readdirSync(d).sort()) {
      const path = join(d, name);
      if (statSync(path).isDirectory()) walk(path);
      else if (name.endsWith('.rs')) {
        out.set(relative(dir, path).replaceAll('\\', '/'), readFileSync(path, 'utf8'));
      }
    }
  };
  walk(dir);
  return out;
}

/** The crates' folders: core-rs/<crate> with a src/. */
export function crateDirs() {
  return readdirSync(join(root, 'core-rs'))
    .sort()
    .filter((c) => existsSync(join(root, 'core-rs', c, 'src')))
    .map((c) => join('core-rs', c));
}

/** The report lines for the crates under `dirs` (relative to the repo root); empty when clean. */
export function report(dirs) {
  const lines = [];
  for (const dir of dirs) {
    const { graph, pathFiles } = crateGraph(rustFiles(resolve(root, dir, 'src')));
    for (const f of pathFiles) lines.push(`${dir}/src/${f}: #[path] modules are not resolved`);
    for (const chains of findCycles(graph)) {
      for (const chain of chains) lines.push(`${dir}/src: ${chain.join(' -> ')}`);
    }
  }
  return lines;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const dirs = process.argv.length > 2 ? process.argv.slice(2) : crateDirs();
  const lines = report(dirs);
  if (lines.length > 0) {
    console.error(`Import cycles between Rust files (see scripts/rust-cycles.mjs):`);
    for (const line of lines) console.error(`  ${line}`);
    process.exitCode = 1;
  } else {
    console.log(`rust-cycles: no import cycles in ${dirs.join(', ')}`);
  }
}
