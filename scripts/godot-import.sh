#!/usr/bin/env bash
# `bash scripts/godot-import.sh [SYLVA_GENERATE_ARGS...]`: imports the strict GLB
# (`sylva generate --strict`, docs/formats.md) into Godot 3 headless (`godot3-server`, Debian's
# package) and checks that the scene loads with its bark and leaf meshes. The default GLB is
# imported too and its result printed for comparison (Godot 3.2 ignores EXT_mesh_gpu_instancing:
# its leaf mesh is one leaf). `scripts/setup.sh --test` installs godot3-server (`apt-get install
# godot3-server`); without it this fails with that advice. The editor imports the files and is then stopped: in server
# mode it does not quit by itself after the import.
set -euo pipefail
cd "$(dirname "$0")/.."
GODOT=${GODOT:-godot3-server}
if ! command -v "$GODOT" >/dev/null; then
  echo "godot-import: $GODOT is not installed: apt-get install godot3-server (scripts/setup.sh --test does), or set GODOT" >&2
  exit 1
fi
SYLVA=$(node -e "import('./scripts/native-cli.mjs').then(m => console.log(m.nativeCli()))")
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
printf 'config_version=4\n\n[application]\nconfig/name="sylva-import"\n' >"$DIR/project.godot"
"$SYLVA" generate "$@" --strict --out "$DIR/strict.glb" >/dev/null
"$SYLVA" generate "$@" --out "$DIR/default.glb" >/dev/null
cat >"$DIR/check.gd" <<'GD'
extends SceneTree
# Loads each imported GLB, counts its mesh instances and surfaces.
func _init():
	for file in ["strict", "default"]:
		var scene = load("res://%s.glb" % file)
		if scene == null:
			print("%s: NOT IMPORTED" % file)
			continue
		var stack = [scene.instance()]
		var found = []
		while stack.size() > 0:
			var node = stack.pop_back()
			if node is MeshInstance and node.mesh != null:
				found.append("%s(%d surfaces, %d vertices)" % [node.name, node.mesh.get_surface_count(), node.mesh.surface_get_arrays(0)[0].size()])
			for child in node.get_children():
				stack.push_back(child)
		found.sort()
		print("%s: IMPORTED %s" % [file, PoolStringArray(found).join(" ")])
	quit()
GD
# The editor's first scan imports both files; stop it once both have an import result (a .scn
# when the import worked, the .md5 either way), or after 240 s.
timeout 240 "$GODOT" --path "$DIR" --editor --quit >"$DIR/editor.log" 2>&1 &
EDITOR=$!
for _ in $(seq 240); do
  [ "$(ls "$DIR"/.import/*.md5 2>/dev/null | wc -l)" -ge 2 ] && sleep 2 && break
  sleep 1
done
kill "$EDITOR" 2>/dev/null || true
wait "$EDITOR" 2>/dev/null || true
OUT=$("$GODOT" --path "$DIR" --script "$DIR/check.gd" 2>/dev/null | grep -E '^(strict|default):' || true)
echo "$OUT"
if ! grep -qE '^strict: IMPORTED bark\([0-9]+ surfaces, [0-9]+ vertices\) leaves\(' <<<"$OUT"; then
  echo "godot-import: the strict GLB did not import with its bark and leaves"
  grep -iE 'error|gltf' "$DIR/editor.log" | grep -v 'free_static\|memory.cpp\|locale' | head -20 || true
  exit 1
fi
echo "godot-import: the strict GLB imports into $("$GODOT" --version)"
