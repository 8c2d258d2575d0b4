#!/usr/bin/env bash
# All lints in one place: rustfmt, no import cycles between Rust files (rust-cycles.mjs), clippy
# (too_many_lines at 120) and rustdoc with warnings as errors (public and private items), eslint (with the size rules), prettier,
# and dependency-cruiser (no TypeScript import cycle; in the web and package `lint` scripts).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo fmt --all --check
node scripts/rust-cycles.mjs
cargo clippy --workspace --all-targets --quiet -- -D warnings
cargo clippy -p sylva-wasm --target wasm32-unknown-unknown --quiet -- -D warnings
RUSTDOCFLAGS='-D warnings' cargo doc --quiet --no-deps --workspace
# The private items' docs too (their links; the public run above checks that public docs link no
# private item), into their own folder.
RUSTDOCFLAGS='-D warnings' cargo doc --quiet --no-deps --workspace --document-private-items \
  --target-dir "${CARGO_TARGET_DIR:-target}/doc-private"
npm run lint -w web
npx tsc --noEmit -p e2e
npm run lint -w packages/sylva-trees
npx eslint scripts eslint.config.mjs
npx prettier --check scripts e2e eslint.config.mjs
