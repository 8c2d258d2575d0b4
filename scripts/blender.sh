#!/usr/bin/env bash
# The Blender add-on (blender/sylva_blender, docs/blender.md).
#   scripts/blender.sh zip    the extension sylva-blender-VERSION.zip at the repository root, with
#                             the sylva-trees wheel bundled (`npm run blender`)
#   scripts/blender.sh venv   the project venv .venv-blender/ with `bpy` (Blender as a Python
#                             module, from PyPI; scripts/setup.sh --test)
#   scripts/blender.sh test   the zip installed into a headless Blender by its extension
#                             installer, then blender/tests/test_addon.py against the CLI
#   scripts/blender.sh growth the growth-animation GLB (`sylva generate --growth-animation`)
#                             imported by Blender's glTF importer: shape keys and an action
#                             (blender/tests/test_growth.py; SYLVA_RENDER_DIR=dir renders frames)
# The wheel is rebuilt when a source is newer (scripts/python.sh), the zip when the wheel or an
# add-on file is newer than it, the venv when its pinned bpy changes: unchanged, each takes a moment.
set -euo pipefail
cd "$(dirname "$0")/.."
step() { printf '\033[1;32m[blender]\033[0m %s\n' "$*"; }
die() { printf '\033[1;31m[blender] error:\033[0m %s\n' "$*" >&2; exit 1; }
what=${1:-zip}
case "$what" in zip | venv | test | growth) ;; *) die "usage: scripts/blender.sh zip|venv|test|growth" ;; esac

# bpy 4.5 LTS is the newest bpy for CPython 3.11 (bpy 5.0 needs 3.13).
BPY='bpy==4.5.*'
VENV=.venv-blender
venv() {
  PYTHON=${PYTHON:-python3}
  if [ ! -x "$VENV/bin/python" ] || [ "$(cat "$VENV/.sylva-tools" 2>/dev/null)" != "$BPY" ]; then
    step "venv $VENV: $BPY (about 370 MB)"
    "$PYTHON" -m venv "$VENV"
    "$VENV/bin/pip" install --quiet --disable-pip-version-check "$BPY"
    echo "$BPY" > "$VENV/.sylva-tools"
  fi
}

addon=blender/sylva_blender
version=$(sed -n 's/^version = "\(.*\)"/\1/p' "$addon/blender_manifest.toml")
zip=sylva-blender-$version.zip
build_zip() {
  bash scripts/python.sh wheel
  wheel=$(ls -t sylva_trees-*.whl | head -n 1)
  if [ ! -f "$zip" ] || [ -n "$(find "$wheel" "$addon" scripts/blender.sh -newer "$zip" -print -quit)" ]; then
    step "$zip (the add-on and $wheel)"
    python3 - "$addon" "$wheel" "$zip" <<'PY'
import re, sys, zipfile
from pathlib import Path
addon, wheel, out = Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3]
with zipfile.ZipFile(out + ".tmp", "w", zipfile.ZIP_DEFLATED) as z:
    for f in sorted(addon.rglob("*")):
        if f.is_file() and "__pycache__" not in f.parts:
            data = f.read_bytes()
            if f.name == "blender_manifest.toml":
                data = re.sub(rb"wheels = \[.*\]", b'wheels = ["./wheels/' + wheel.name.encode() + b'"]', data)
            z.writestr(str(f.relative_to(addon)), data)
    z.write(wheel, f"wheels/{wheel.name}")
PY
    mv "$zip.tmp" "$zip"
  fi
  step "$zip ($(du -k "$zip" | cut -f1) KiB)"
}

case "$what" in
  venv) venv ;;
  zip) build_zip ;;
  test)
    venv
    build_zip
    cargo build --quiet --release -p sylva-cli
    step "install $zip into a headless Blender; add, edit and share a tree"
    SYLVA_CLI="$PWD/${CARGO_TARGET_DIR:-target}/release/sylva" SYLVA_BLENDER_ZIP="$PWD/$zip" \
      "$VENV/bin/python" blender/tests/test_addon.py
    ;;
  growth)
    venv
    cargo build --quiet --release -p sylva-cli
    step "the growth-animation GLB in Blender's glTF importer: shape keys and an action"
    SYLVA_CLI="$PWD/${CARGO_TARGET_DIR:-target}/release/sylva" "$VENV/bin/python" blender/tests/test_growth.py
    ;;
esac
