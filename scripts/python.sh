#!/usr/bin/env bash
# The Python package `sylva-trees` (core-rs/sylva-py, docs/python.md).
#   scripts/python.sh wheel   the abi3 wheel for this platform into the repository root
#                             (sylva_trees-VERSION-cp39-abi3-PLATFORM.whl); `npm run wheel`
#   scripts/python.sh test    the wheel, installed into the venv, then its pytest suite against
#                             the release `sylva` binary (same hashes, same export bytes)
# Tools live in a project venv, .venv-py/ (maturin, numpy, pytest from PyPI; not in git). The
# wheel is rebuilt only when a Rust source, Cargo file or the Python package is newer than it.
set -euo pipefail
cd "$(dirname "$0")/.."
step() { printf '\033[1;32m[python]\033[0m %s\n' "$*"; }
die() { printf '\033[1;31m[python] error:\033[0m %s\n' "$*" >&2; exit 1; }
what=${1:-wheel}
[ "$what" = wheel ] || [ "$what" = test ] || die "usage: scripts/python.sh wheel|test"

PYTHON=${PYTHON:-python3}
command -v "$PYTHON" >/dev/null || die "python3 not found: install Python 3.9 or newer"
VENV=.venv-py
TOOLS='maturin>=1.9,<2 numpy>=1.21 pytest>=8,<10'
if [ ! -x "$VENV/bin/python" ] || [ "$(cat "$VENV/.sylva-tools" 2>/dev/null)" != "$TOOLS" ]; then
  step "venv $VENV: $TOOLS"
  "$PYTHON" -m venv "$VENV"
  # shellcheck disable=SC2086 # the tool list splits into requirements on purpose
  "$VENV/bin/pip" install --quiet --disable-pip-version-check $TOOLS
  echo "$TOOLS" > "$VENV/.sylva-tools"
fi

wheel=$(ls -t sylva_trees-*.whl 2>/dev/null | head -n 1 || true)
sources=(Cargo.toml Cargo.lock core-rs/sylva-core/src core-rs/sylva-py/src core-rs/sylva-py/python
  core-rs/sylva-py/Cargo.toml core-rs/sylva-py/pyproject.toml)
if [ -z "$wheel" ] || [ -n "$(find "${sources[@]}" -newer "$wheel" -print -quit)" ]; then
  step "maturin build --release (abi3 wheel)"
  rm -f sylva_trees-*.whl
  "$VENV/bin/maturin" build --quiet --release -m core-rs/sylva-py/Cargo.toml --out .
  wheel=$(ls -t sylva_trees-*.whl | head -n 1)
fi
step "$wheel ($(du -k "$wheel" | cut -f1) KiB)"
[ "$what" = test ] || exit 0

step "pip install $wheel; cargo build the release sylva CLI; pytest"
"$VENV/bin/pip" install --quiet --disable-pip-version-check --force-reinstall --no-deps "$wheel"
cargo build --quiet --release -p sylva-cli
# From the tests' folder, so `import sylva_trees` is the installed wheel, not a source tree.
SYLVA_CLI="$PWD/${CARGO_TARGET_DIR:-target}/release/sylva" "$VENV/bin/python" -m pytest -q -p no:cacheprovider \
  core-rs/sylva-py/tests
