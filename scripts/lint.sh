#!/usr/bin/env bash
# All lints in one place: rustfmt, clippy and rustdoc with warnings as errors, eslint (with the size
# rule), prettier, and dependency-cruiser (no import cycle; in the web and package `lint` scripts).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo fmt --all --check
cargo clippy --workspace --all-targets --quiet -- -D warnings
cargo clippy -p sylva-wasm --target wasm32-unknown-unknown --quiet -- -D warnings
RUSTDOCFLAGS='-D warnings' cargo doc --quiet --no-deps --workspace
npm run lint -w web
npx tsc --noEmit -p e2e
npm run lint -w packages/sylva-trees
npx eslint scripts eslint.config.mjs
npx prettier --check scripts e2e eslint.config.mjs
