// The size rule (sizes.mjs): no source file in core-rs/*/src or web/src over 500 lines, no
// function over 120 (tests and generated files aside).
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { ALLOWED, blank, describe, functions, key, offenders, rustSourceDirs } from './sizes.mjs';

const lengths = (text, lang) => functions(text, lang).map((f) => `${f.name}:${f.lines}`);

test('Rust functions are measured from fn to their closing brace, literals and comments aside', () => {
  const text = [
    "pub(crate) fn a<'a>(x: &'a str) -> char {", // 1
    '    let s = "}}"; let r = r#"{"#; let c = \'{\'; // }',
    '    /* { /* nested */ } */',
    '    fn inner() { let _ = b"{"; }',
    "    '}'",
    '}', // 6
    'trait T { fn decl(&self); }',
    'impl X {',
    '    const fn b(&self)',
    '    where Self: Sized',
    '    {}',
    '}',
  ].join('\n');
  assert.deepEqual(lengths(text, 'rs'), ['a:6', 'inner:1', 'b:3']);
});

test('TypeScript functions, methods and arrow bodies, with templates and JSX text', () => {
  const text = [
    'export function App(): JSX.Element {', // 1
    '  const s = `a ${`{${1}`} }`;',
    '  const f = async (x: number) => {',
    "    return <p>Don't {x}</p>;",
    '  };',
    '  if (s) {',
    '  }',
    '  return <div/>;',
    '}', // 9
    'class C {',
    '  method(a: string): void {',
    '  }',
    '}',
  ].join('\n');
  assert.deepEqual(lengths(text, 'ts'), ['App:9', 'f:3', 'method:2']);
  assert.equal(blank('"{"', 'ts'), '   ');
});

/** Every folder the rule covers: the Rust crates' sources and the web app's. */
const covered = () => [...rustSourceDirs(), 'web/src'];

test('the allow-list names only offenders that still exist', () => {
  const keys = offenders(covered()).map(key);
  assert.deepEqual(
    ALLOWED.filter((k) => !keys.includes(k)),
    [],
  );
});

test('no file in core-rs/*/src or web/src over 500 lines, no function over 120 (sizes.mjs)', () => {
  const list = offenders(covered()).filter((o) => !ALLOWED.includes(key(o)));
  assert.deepEqual(describe(list), []);
});
