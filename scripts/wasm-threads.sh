#!/usr/bin/env bash
# The core's wasm module built with threads (called by scripts/setup.sh):
#   scripts/wasm-threads.sh OUT_DIR [CARGO_FEATURES]
# The same crate as the single-threaded module, compiled with atomics and bulk memory and linked
# with a shared, imported memory, so that helper workers can instantiate it on the generating
# instance's memory (sylva-core `par::helpers`). The standard library must be rebuilt with
# atomics (`-Z build-std`), which only a nightly toolchain does: the one pinned below, with its
# rust-src, installed by rustup once. The bytes a generation gives are the same as the
# single-threaded module's (scripts/wasm-parity.mjs checks both against the native CLI).
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=$1
FEATURES=${2:-}
# Pinned: the threaded module is built by this exact compiler (a newer nightly may change what
# build-std needs); `rustup toolchain install` of a dated nightly takes seconds.
NIGHTLY=nightly-2026-05-19
step() { printf '\033[1;32m[setup]\033[0m %s\n' "$*"; }
die() { printf '\033[1;31m[setup] error:\033[0m %s\n' "$*" >&2; exit 1; }

command -v rustup >/dev/null \
  || die "the threaded wasm module needs rustup (for the $NIGHTLY toolchain): install Rust from https://rustup.rs"
if ! rustup run "$NIGHTLY" rustc --print sysroot >/dev/null 2>&1 \
  || [ ! -d "$(rustup run "$NIGHTLY" rustc --print sysroot)/lib/rustlib/src/rust/library" ]; then
  step "rustup toolchain install $NIGHTLY (rust-src, for the threaded wasm module)"
  rustup toolchain install "$NIGHTLY" --profile minimal --component rust-src
fi

TARGET_DIR=${CARGO_TARGET_DIR:-target}/wasm-threads${FEATURES:+-$FEATURES}
step "cargo build sylva-wasm with threads${FEATURES:+ --features $FEATURES} (release, wasm32, atomics)"
# The memory: shared (helpers instantiate the module on it), imported (created by the glue) and
# at most 4 GiB; the thread-local storage symbols let wasm-bindgen set up each thread's.
RUSTFLAGS="-C target-feature=+atomics,+bulk-memory,+mutable-globals \
-C link-arg=--shared-memory -C link-arg=--import-memory -C link-arg=--max-memory=4294967296 \
-C link-arg=--export=__wasm_init_tls -C link-arg=--export=__tls_size \
-C link-arg=--export=__tls_align -C link-arg=--export=__tls_base" \
  cargo "+$NIGHTLY" build --quiet --release --target wasm32-unknown-unknown -p sylva-wasm \
  -Z build-std=panic_abort,std ${FEATURES:+--features "$FEATURES"} --target-dir "$TARGET_DIR" \
  2> >(grep -v -e 'unstable feature specified for `-Ctarget-feature`: `atomics`' \
    -e 'this feature is not stably supported' -e '^ *|$' -e '^ *= note:' -e '^$' >&2 || true)
WASM=$TARGET_DIR/wasm32-unknown-unknown/release/sylva_wasm.wasm
if [ ! -f "$OUT/sylva_wasm_bg.wasm" ] || [ "$WASM" -nt "$OUT/sylva_wasm_bg.wasm" ]; then
  step "wasm-bindgen -> $OUT"
  wasm-bindgen --target web --out-dir "$OUT" "$WASM"
fi
