// The Rust import-cycle checker (rust-cycles.mjs) on small crates written inline.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { crateGraph, expandUseTree, findCycles, modulePathOf, stripCode } from './rust-cycles.mjs';

/** The cycles of a crate given as `{ 'path/in/src.rs': text }`. */
const cycles = (files) => findCycles(crateGraph(new Map(Object.entries(files))).graph);
const edges = (files) =>
  Object.fromEntries(
    [...crateGraph(new Map(Object.entries(files))).graph].map(([f, d]) => [f, [...d].sort()]),
  );

test('two files importing each other are a cycle, reported as a chain of files', () => {
  const crate = {
    'lib.rs': 'pub mod a;\npub mod b;\n',
    'a.rs': 'use crate::b::Frame;\npub struct Mesh;\n',
    'b.rs': 'pub struct Frame;\npub fn f(m: &crate::a::Mesh) {}\n',
  };
  assert.deepEqual(cycles(crate), [[['a.rs', 'b.rs', 'a.rs']]]);
});

test('a chain without a way back is no cycle', () => {
  const crate = {
    'lib.rs': 'pub mod a;\npub mod b;\npub mod c;\n',
    'a.rs': 'use crate::b::{self, X};\nfn f() { b::g(); }\n',
    'b.rs': 'use super::c::Y;\npub struct X;\npub fn g() {}\n',
    'c.rs': 'pub struct Y;\n',
  };
  assert.deepEqual(edges(crate), { 'a.rs': ['b.rs'], 'b.rs': ['c.rs'], 'c.rs': [], 'lib.rs': [] });
  assert.deepEqual(cycles(crate), []);
});

test('a re-export is an edge of the file that holds it, and a path to it goes to that file', () => {
  const crate = {
    'lib.rs': 'pub mod session;\npub use session::Session;\npub struct Generated;\n',
    'session/mod.rs':
      'mod stages;\npub struct Session;\nfn g() -> crate::Generated { crate::Generated }\n',
    'session/stages.rs': 'use super::Session;\n',
  };
  assert.deepEqual(cycles(crate), [[['lib.rs', 'session/mod.rs', 'lib.rs']]]);
  // Without the re-export, nothing in lib.rs names the session.
  crate['lib.rs'] = 'pub mod session;\npub struct Generated;\n';
  assert.deepEqual(cycles(crate), []);
});

test('a child module name used in code is an edge (a crate root calling its session)', () => {
  const crate = {
    'lib.rs':
      'pub mod session;\npub struct Stats;\npub fn generate() { session::Session::new(); }\n',
    'session.rs': 'use crate::Stats;\npub struct Session;\n',
  };
  assert.deepEqual(cycles(crate), [[['lib.rs', 'session.rs', 'lib.rs']]]);
});

test("a private child's uses of its ancestors are not edges; a public child's are", () => {
  const crate = {
    'lib.rs': 'pub mod tube;\n',
    'tube/mod.rs': 'mod plan;\npub struct Frame;\npub fn build() { plan::run(); }\n',
    'tube/plan.rs': 'use super::Frame;\npub fn run() {}\n',
  };
  assert.deepEqual(cycles(crate), []);
  crate['tube/mod.rs'] = crate['tube/mod.rs'].replace('mod plan;', 'pub mod plan;');
  assert.deepEqual(cycles(crate), [[['tube/mod.rs', 'tube/plan.rs', 'tube/mod.rs']]]);
});

test('a cycle through a private child still counts when it leaves the parent', () => {
  const crate = {
    'lib.rs': 'pub mod holes;\npub mod tube;\n',
    'tube/mod.rs': 'mod plan;\npub fn drop_close() {}\npub fn build() { plan::run(); }\n',
    'tube/plan.rs': 'use crate::holes;\npub fn run() { holes::eligible(); }\n',
    'holes.rs': 'pub fn eligible() { super::tube::drop_close(); }\n',
  };
  assert.deepEqual(cycles(crate), [[['holes.rs', 'tube/mod.rs', 'tube/plan.rs', 'holes.rs']]]);
});

test('siblings under one parent in a cycle are reported, and every file of a big cycle is shown', () => {
  const crate = {
    'lib.rs': 'pub mod holes;\n',
    'holes/mod.rs': 'mod cavity;\nmod cut;\nmod patch;\n',
    'holes/cavity.rs': 'use super::cut::Region;\npub struct Cavity;\n',
    'holes/cut.rs': 'use super::patch::P;\npub struct Region;\n',
    'holes/patch.rs': 'use super::cavity::Cavity;\npub struct P;\n',
  };
  assert.deepEqual(cycles(crate), [
    [['holes/cavity.rs', 'holes/cut.rs', 'holes/patch.rs', 'holes/cavity.rs']],
  ]);
});

test('test modules, comments, strings, doc links and other crates are not edges', () => {
  const crate = {
    'lib.rs': 'pub mod a;\npub mod b;\n',
    'a.rs': ['use crate::b::X;', '#[cfg(test)]', 'mod tests;', 'pub struct Y;'].join('\n'),
    'a/tests.rs': 'use crate::a::Y;',
    'b.rs': [
      '//! See [`crate::a::Y`].',
      'use std::ops::Range;',
      'use glam::Vec3;',
      'pub struct X;',
      '// crate::a::Y is mentioned here',
      'const S: &str = "crate::a::Y";',
      "const C: char = '{';",
      'macro_rules! m { () => { $crate::a::Y } }',
      '#[cfg(test)]',
      'mod tests {',
      '    use crate::a::Y;',
      '    fn f() { let _ = crate::a::Y; }',
      '}',
    ].join('\n'),
  };
  assert.deepEqual(edges(crate), { 'a.rs': ['b.rs'], 'b.rs': [], 'lib.rs': [] });
});

test('use trees expand to their leaves, with the names they bind', () => {
  assert.deepEqual(expandUseTree('crate::mesh::{self, tube::{Frame as F, StemMesh}, weld::*}'), [
    { segs: ['crate', 'mesh'], binds: 'mesh' },
    { segs: ['crate', 'mesh', 'tube', 'Frame'], binds: 'F' },
    { segs: ['crate', 'mesh', 'tube', 'StemMesh'], binds: 'StemMesh' },
    { segs: ['crate', 'mesh', 'weld'], binds: null },
  ]);
});

test('an alias bound by use resolves the paths in code that start with it', () => {
  const crate = {
    'lib.rs': 'pub mod mesh;\npub mod session;\n',
    'mesh/mod.rs': 'pub mod tube;\n',
    'mesh/tube.rs': 'pub fn build() {}\n',
    'session.rs': 'use crate::mesh;\nfn f() { mesh::tube::build(); }\n',
  };
  assert.deepEqual(edges(crate)['session.rs'], ['mesh/mod.rs', 'mesh/tube.rs']);
});

test('module paths follow the file layout, inline modules included', () => {
  assert.deepEqual(modulePathOf('lib.rs'), []);
  assert.deepEqual(modulePathOf('main.rs'), []);
  assert.deepEqual(modulePathOf('mesh/mod.rs'), ['mesh']);
  assert.deepEqual(modulePathOf('mesh/tube/plan.rs'), ['mesh', 'tube', 'plan']);
  const crate = {
    'lib.rs': 'pub mod a;\npub mod b;\n',
    'a.rs': 'pub mod inner {\n    pub fn g() { super::super::b::h(); }\n}\n',
    'b.rs': 'pub fn h() {}\npub fn k() { crate::a::inner::g(); }\n',
  };
  assert.deepEqual(cycles(crate), [[['a.rs', 'b.rs', 'a.rs']]]);
});

test('stripping keeps offsets and lines, and tells lifetimes from char literals', () => {
  const text =
    "fn f<'a>(x: &'a str) -> char { let s = r#\"crate::a\"#; 'x' } // crate::b\n/* crate::c */";
  const out = stripCode(text);
  assert.equal(out.length, text.length);
  assert.ok(!/crate::/.test(out), out);
  assert.ok(out.includes("fn f<'a>(x: &'a str)"), out);
});
