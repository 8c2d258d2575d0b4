#!/usr/bin/env bash
# One setup for every entry point (npm start, npm test, npm run build/bench/lint).
# Idempotent: each step checks before it acts, so a second run with nothing changed takes seconds.
#   scripts/setup.sh            npm deps, wasm32 target, pinned wasm-bindgen CLI, release wasm build,
#                               and the same with threads (scripts/wasm-threads.sh: a pinned nightly)
#   scripts/setup.sh --test     the same, plus the debug wasm builds (the test hooks `debug_panic`,
#                               `debug_panic_on_helper`, `debug_near_x`, in packages/sylva-trees/src/wasm-debug and
#                               wasm-threads-debug), Chromium for the Playwright tests
#                               and the Python package's venv and wheel (scripts/python.sh)
#   scripts/setup.sh --native   the same as plain (the bench also builds the native CLI itself)
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
WANT_TEST=0
for a in "$@"; do [ "$a" = "--test" ] && WANT_TEST=1; done

WASM_BINDGEN_VERSION=$(sed -n 's/^wasm-bindgen = "=\(.*\)"/\1/p' core-rs/sylva-wasm/Cargo.toml)
step() { printf '\033[1;32m[setup]\033[0m %s\n' "$*"; }
die() { printf '\033[1;31m[setup] error:\033[0m %s\n' "$*" >&2; exit 1; }

command -v cargo >/dev/null || die "cargo not found: install Rust from https://rustup.rs, then run this again"
command -v node >/dev/null || die "node not found: install Node.js 20.19 or newer"
node -e 'const [a,b]=process.versions.node.split(".").map(Number); process.exit(a>20||(a===20&&b>=19)?0:1)' \
  || die "Node.js $(node --version) is too old: Vite 8 needs 20.19 or newer"

# 1. npm dependencies, from the lockfile, only when the lockfile changed since the last install.
lock_sum=$(sha256sum package-lock.json | cut -d' ' -f1)
if [ ! -f node_modules/.sylva-lock ] || [ "$(cat node_modules/.sylva-lock)" != "$lock_sum" ]; then
  step "npm ci"
  npm ci --no-audit --no-fund
  echo "$lock_sum" > node_modules/.sylva-lock
fi

# 2. The wasm32 target.
if command -v rustup >/dev/null; then
  if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
    step "rustup target add wasm32-unknown-unknown"
    rustup target add wasm32-unknown-unknown
  fi
else
  rustc --print target-libdir --target wasm32-unknown-unknown >/dev/null 2>&1 \
    || die "no rustup and no wasm32-unknown-unknown standard library: install the target for your Rust"
fi

# 3. The wasm-bindgen CLI, the exact version the binding crate pins (a mismatch breaks the glue).
if [ "$(wasm-bindgen --version 2>/dev/null | cut -d' ' -f2)" != "$WASM_BINDGEN_VERSION" ]; then
  step "cargo install wasm-bindgen-cli $WASM_BINDGEN_VERSION (compiles once, about 6 minutes)"
  cargo install wasm-bindgen-cli --version "$WASM_BINDGEN_VERSION"
fi

# 4. The release wasm build and its JS glue in packages/sylva-trees/src/wasm (cargo itself is a no-op when nothing changed).
step "cargo build sylva-wasm (release, wasm32)"
cargo build --quiet --release --target wasm32-unknown-unknown -p sylva-wasm
WASM=${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/release/sylva_wasm.wasm
OUT=packages/sylva-trees/src/wasm
if [ ! -f "$OUT/sylva_wasm_bg.wasm" ] || [ "$WASM" -nt "$OUT/sylva_wasm_bg.wasm" ]; then
  step "wasm-bindgen -> $OUT"
  wasm-bindgen --target web --out-dir "$OUT" "$WASM"
fi

# 4b. The same module built with threads (atomics, a shared memory; a pinned nightly compiles it),
#     in packages/sylva-trees/src/wasm-threads: the worker loads it where the page is
#     cross-origin isolated, and starts a helper worker on its memory.
bash scripts/wasm-threads.sh packages/sylva-trees/src/wasm-threads

# 5. For tests: the same module with the `debug-hooks` feature (`debug_panic`, for the tests of
#    the worker's crash recovery) in its own target directory and folder, which only the app's
#    debug build (`npm run build:debug -w web`, web/dist-debug) loads. cargo is a no-op when
#    nothing changed, and wasm-bindgen runs only when the module is newer than its glue.
if [ "$WANT_TEST" = 1 ]; then
  step "cargo build sylva-wasm --features debug-hooks (release, wasm32)"
  DEBUG_TARGET=${CARGO_TARGET_DIR:-target}/debug-hooks
  cargo build --quiet --release --target wasm32-unknown-unknown -p sylva-wasm --features debug-hooks \
    --target-dir "$DEBUG_TARGET"
  DEBUG_WASM=$DEBUG_TARGET/wasm32-unknown-unknown/release/sylva_wasm.wasm
  DEBUG_OUT=packages/sylva-trees/src/wasm-debug
  if [ ! -f "$DEBUG_OUT/sylva_wasm_bg.wasm" ] || [ "$DEBUG_WASM" -nt "$DEBUG_OUT/sylva_wasm_bg.wasm" ]; then
    step "wasm-bindgen -> $DEBUG_OUT"
    wasm-bindgen --target web --out-dir "$DEBUG_OUT" "$DEBUG_WASM"
  fi
  # And the threaded module with them (`debug_panic_on_helper`: a helper thread's panic).
  bash scripts/wasm-threads.sh packages/sylva-trees/src/wasm-threads-debug debug-hooks
fi

# 6. For tests: Chromium from the system (Playwright's own browser download is never used).
if [ "$WANT_TEST" = 1 ]; then
  CHROMIUM=${SYLVA_CHROMIUM:-/usr/bin/chromium}
  if [ ! -x "$CHROMIUM" ]; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
      step "apt-get install chromium"
      apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null
    else
      die "Chromium is needed for the browser tests and $CHROMIUM is missing: install it (Debian/Ubuntu: sudo apt-get install chromium) or set SYLVA_CHROMIUM to a Chromium binary"
    fi
  fi
fi
# 7. For tests: Godot 3 headless from the system (Debian's godot3-server), which imports the
#    strict GLB (scripts/godot-import.sh); a missing Godot that cannot be installed is an error.
if [ "$WANT_TEST" = 1 ] && ! command -v "${GODOT:-godot3-server}" >/dev/null; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
    step "apt-get install godot3-server"
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq godot3-server >/dev/null
  else
    die "Godot 3 is needed to import the strict GLB in the tests: install it (Debian/Ubuntu: sudo apt-get install godot3-server) or set GODOT to a Godot 3 binary"
  fi
fi
# 8. For tests: the venv with maturin, numpy and pytest (.venv-py) and the sylva-trees wheel
#    (scripts/python.sh; rebuilt only when a Rust or Python source is newer than the wheel).
if [ "$WANT_TEST" = 1 ]; then
  command -v python3 >/dev/null || die "python3 not found: the Python package's tests need Python 3.9 or newer with venv"
  step "Python package: venv and wheel (scripts/python.sh wheel)"
  bash scripts/python.sh wheel
  # 9. For tests: Blender as a Python module (bpy 4.5 from PyPI) in .venv-blender, once.
  step "Blender add-on: the bpy venv (scripts/blender.sh venv)"
  bash scripts/blender.sh venv
fi
step "ready ($(( SECONDS ))s)"
cd "$ROOT"
