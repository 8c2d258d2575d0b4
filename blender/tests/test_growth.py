"""The growth-animation GLB in a headless Blender (`bpy` from PyPI): `sylva generate
--growth-animation` writes it, Blender's glTF importer reads it, and the bark and the leaves come
in with one shape key per key year (plus the basis) and an action on their shape keys whose
frames run from year 0 to the Age at the scene's frame rate (one second a year). Run by
scripts/blender.sh growth; exits non-zero on the first failure. Optional: SYLVA_RENDER_DIR=dir
renders the tree at a few years into dir/growth-YEAR.png."""

import json
import os
import struct
import subprocess
import tempfile
from pathlib import Path

_home = tempfile.mkdtemp(prefix="sylva-blender-")
os.environ["BLENDER_USER_RESOURCES"] = _home

import bpy  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("SYLVA_CLI") or str(ROOT / "target/release/sylva")


def export(path, *args):
    """`sylva generate ARGS --growth-animation --out PATH` and the file's glTF JSON."""
    subprocess.run([CLI, "generate", *args, "--growth-animation", "--out", str(path)], check=True, capture_output=True)
    glb = path.read_bytes()
    return json.loads(glb[20 : 20 + struct.unpack_from("<I", glb, 12)[0]])


def action_of(key):
    """The action animating shape-key block `key` and its fcurves (Blender 4.4+ keeps them in a
    slot's channelbag, older ones on the action)."""
    action = key.animation_data.action if key.animation_data else None
    assert action is not None, f"{key.name}: no action on the shape keys"
    curves = list(getattr(action, "fcurves", []))
    if not curves and hasattr(action, "layers"):
        slot = key.animation_data.action_slot
        for layer in action.layers:
            for strip in layer.strips:
                bag = strip.channelbag(slot)
                curves.extend(bag.fcurves if bag else [])
    return action, curves


def check(label, args, age):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    path = Path(_home) / f"{label}.glb"
    doc = export(path, *args)
    years = doc["animations"][0]["extras"]["key_years"]
    assert years[0] == 0 and abs(years[-1] - age) < 1e-4, years
    assert bpy.ops.import_scene.gltf(filepath=str(path)) == {"FINISHED"}
    fps = bpy.context.scene.render.fps / bpy.context.scene.render.fps_base
    meshes = [o for o in bpy.data.objects if o.type == "MESH"]
    assert {o.name for o in meshes} >= {"bark", "leaves"}, [o.name for o in meshes]
    for o in meshes:
        key = o.data.shape_keys
        assert key is not None, f"{o.name}: no shape keys"
        names = [b.name for b in key.key_blocks]
        # The basis, then one key per key year before the Age, named after the year.
        assert len(names) == len(years), (o.name, names, years)
        assert names[1:] == [f"year {y:g}" for y in years[:-1]], names
        action, curves = action_of(key)
        assert len(curves) == len(years) - 1, (o.name, len(curves))
        first, last = action.frame_range
        span = (last - first) / fps
        assert abs(span - age) < 0.05, f"{o.name}: {action.name} spans {span} s, the Age is {age}"
        # Mid-way between the first two keys the first key's shape is half on.
        mid = first + 0.5 * (years[1] - years[0]) * fps
        bpy.context.scene.frame_set(int(round(mid)))
        w = key.key_blocks[1].value
        assert 0.2 < w < 0.8, f"{o.name}: weight {w} at frame {mid}"
        print(f"{label} {o.name}: {len(names) - 1} shape keys, action {action.name} frames {first:g}..{last:g}")
    render_dir = os.environ.get("SYLVA_RENDER_DIR")
    if render_dir:
        render(Path(render_dir), label, years, fps)


def render(out, label, years, fps):
    """Workbench pictures of the tree at a few years (the camera frames the tree as built)."""
    scene = bpy.context.scene
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(camera)
    # The meshes' own positions: the tree as built (the bounds follow the current frame's shape).
    top = max((o.matrix_world @ v.co).z for o in bpy.data.objects if o.type == "MESH" for v in o.data.vertices)
    camera.location = (0, -2.6 * top, 0.5 * top)
    camera.rotation_euler = (1.57, 0, 0)
    scene.camera = camera
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.display.shading.color_type = "MATERIAL"
    scene.render.resolution_x, scene.render.resolution_y = 320, 400
    out.mkdir(parents=True, exist_ok=True)
    for y in [years[-1] * f for f in (0.1, 0.25, 0.5, 1.0)]:
        scene.frame_set(int(round(y * fps)))
        scene.render.filepath = str(out / f"{label}-growth-{y:04.1f}.png")
        bpy.ops.render.render(write_still=True)


def main():
    check("default", [], 40)
    check("grown_broadleaf", ["--preset", "grown_broadleaf"], 35)
    # Past its Mature Age (40): keys at 40, 45, 50, 55 and the Age, the limbs sinking.
    check("default-aged", ["--age", "60", "--set", "leaves=6"], 60)
    print("growth animation: imported with shape keys and an action")


if __name__ == "__main__":
    # A failed check raises: Python prints it and exits with status 1.
    main()
