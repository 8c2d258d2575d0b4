#!/usr/bin/env bash
# Every test, in the order that fails fastest. Called by `npm test` after scripts/setup.sh --test.
set -euo pipefail
cd "$(dirname "$0")/.."
step() { printf '\n\033[1;36m[test]\033[0m %s\n' "$*"; }

step "lint (rustfmt, clippy -D warnings, eslint, prettier)"
bash scripts/lint.sh
step "scripts: node --test (the Node scripts' own helpers)"
node --test scripts/
step "Rust: cargo test --workspace"
cargo test --workspace --quiet
step "Python: the sylva-trees wheel against the CLI (pytest; the wheel is rebuilt only when a source changed)"
bash scripts/python.sh test
step "Blender: the add-on zip installed into headless Blender; add, edit and share a tree (zip rebuilt only when changed)"
bash scripts/blender.sh test
step "Blender: the growth-animation GLB imports with shape keys and an action"
bash scripts/blender.sh growth
step "glTF: every preset's GLB (instanced, baked and strict) through the Khronos validator"
node scripts/validate-gltf.mjs
step "Godot: the strict GLB imports into godot3-server (installed by setup.sh --test)"
bash scripts/godot-import.sh
step "wasm vs native: same content hashes"
node scripts/wasm-parity.mjs
step "Vitest"
npm run test -w web
npm run test -w packages/sylva-trees
step "build the web app, its debug build (the worker's test hooks, for e2e), and the sylva-trees package (tarball for its e2e test)"
npm run build -w web
npm run build:debug -w web
bash scripts/package.sh
step "Playwright (Chromium)"
npm run test -w e2e
