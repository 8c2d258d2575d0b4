"""The Blender add-on end to end in a headless Blender (`bpy` from PyPI): the extension zip is
installed by Blender's own extension installer into a throwaway user folder, then a tree is
added, checked (objects, materials, textures, wind attributes, one instanced leaf per leaf, the
CLI's hash), edited (a parameter change regrows it, again the CLI's hash) and exchanged through
share links (the studio's fixture links, a copied link pasted back). Run by scripts/blender.sh
test; exits non-zero on the first failure. Optional: SYLVA_RENDER=path.png renders the tree."""

import json
import os
import struct
import subprocess
import tempfile
from pathlib import Path

# Blender reads its user folders once, at import: a throwaway one keeps the real one untouched.
_home = tempfile.mkdtemp(prefix="sylva-blender-")
os.environ["BLENDER_USER_RESOURCES"] = _home

import bpy  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("SYLVA_CLI") or str(ROOT / "target/release/sylva")
ZIP = os.environ["SYLVA_BLENDER_ZIP"]
FIXTURES = json.loads((ROOT / "core-rs/sylva-core/tests/share_links.json").read_text())["links"]


def cli(*args):
    """`sylva generate ARGS`'s JSON report."""
    out = subprocess.run([CLI, "generate", *args], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def cli_leaves(*args):
    """`sylva generate ARGS --out tree.glb`'s leaf count: the instances of its leaf node."""
    path = Path(_home) / "tree.glb"
    cli(*args, "--out", str(path))
    glb = path.read_bytes()
    doc = json.loads(glb[20 : 20 + struct.unpack_from("<I", glb, 12)[0]])
    counts = [
        doc["accessors"][n["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["TRANSLATION"]]["count"]
        for n in doc["nodes"]
        if "EXT_mesh_gpu_instancing" in n.get("extensions", {})
    ]
    return sum(counts)


def instances_of(obj):
    """How many instances the evaluated `obj` draws."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    return sum(1 for i in depsgraph.object_instances if i.is_instance and i.parent and i.parent.name == obj.name)


def install():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    result = bpy.ops.extensions.package_install_files(filepath=ZIP, repo="user_default", enable_on_install=True)
    assert result == {"FINISHED"}, result
    assert "bl_ext.user_default.sylva_blender" in bpy.context.preferences.addons, "the add-on is enabled"
    assert hasattr(bpy.ops.mesh, "sylva_tree_add")


def test_add(preset="quaking_aspen", seed=7):
    assert bpy.ops.mesh.sylva_tree_add(preset=preset, seed=seed) == {"FINISHED"}
    bark = bpy.context.active_object
    s = bark.sylva
    want = cli("--preset", preset, "--seed", str(seed))
    want["leaves"] = cli_leaves("--preset", preset, "--seed", str(seed))
    assert s.is_tree and s.tree_hash == want["hash"], (s.tree_hash, want["hash"])
    # Objects: the bark mesh, the hidden leaf shape, the leaves as one object of points.
    assert len(bark.data.vertices) == want["vertices"] and len(bark.data.polygons) == want["triangles"]
    leaves, shape = s.leaves_object, s.leaf_shape_object
    assert leaves.parent == bark and shape.parent == bark and shape.hide_render
    assert len(leaves.data.vertices) == want["leaves"] > 1000
    assert instances_of(leaves) == want["leaves"], (instances_of(leaves), want["leaves"])
    # Materials with the core's textures, packed into the file.
    assert [m.name for m in bark.data.materials] == [f"{bark.name} bark", f"{bark.name} cut_face"]
    leaf_material = shape.data.materials[0]
    nodes = [n for m in (*bark.data.materials, leaf_material) for n in m.node_tree.nodes]
    images = {n.image.name for n in nodes if n.type == "TEX_IMAGE"}
    assert {f"{bark.name} {k}" for k in ("bark_color", "bark_normal", "leaf_color", "leaf_normal")} <= images
    assert all(bpy.data.images[i].packed_file and bpy.data.images[i].size[0] > 0 for i in images)
    # The wind records as attributes of every bark vertex; the trunk sways about its base.
    for name in ("wind_pivot", "wind_level", "wind_phase", "wind_stiffness", "wind_distance", "wind_radius"):
        assert len(bark.data.attributes[name].data) == want["vertices"], name
    levels = [0.0] * want["vertices"]
    bark.data.attributes["wind_level"].data.foreach_get("value", levels)
    assert {0, 1, 2} <= {round(v) for v in levels} <= {0, 1, 2, 3}
    return bark


def test_a_change_regrows(bark):
    before = bark.sylva.tree_hash
    bark.sylva.l1_branches = 12
    want = cli("--preset", "quaking_aspen", "--seed", "7", "--set", "l1_branches=12")
    want["leaves"] = cli_leaves("--preset", "quaking_aspen", "--seed", "7", "--set", "l1_branches=12")
    assert bark.sylva.tree_hash == want["hash"] != before
    assert len(bark.sylva.leaves_object.data.vertices) == want["leaves"] == instances_of(bark.sylva.leaves_object)
    bark.sylva.season = 10.35  # Age and Season are parameters like the rest (a float32 in Blender).
    bark.sylva.age = 12.5
    want = cli(
        "--preset", "quaking_aspen", "--seed", "7", "--set", "l1_branches=12", "--set", "season=10.35",
        "--set", "age=12.5",
    )
    assert bark.sylva.tree_hash == want["hash"], (bark.sylva.tree_hash, want["hash"])


def test_share_links(bark):
    # The studio's links (the fixtures its codec writes) open the same trees the CLI grows.
    for f in FIXTURES:
        if f["name"] in ("a preset and a seed", "numbers of every kind", "hand edits"):
            assert bpy.ops.sylva.paste_share_link(link="http://localhost:5173/?" + f["link"]) == {"FINISHED"}
            want = sylva_hash(f)
            assert bark.sylva.tree_hash == want and bark.sylva.preset == "CUSTOM", (f["name"], bark.sylva.tree_hash)
    # A copied link is the studio's link of the same tree, and pasting it back changes nothing.
    assert bpy.ops.sylva.copy_share_link() == {"FINISHED"}
    link = bark["sylva_share_link"]
    assert link == "http://localhost:5173/?" + FIXTURES[4]["link"], link
    before = bark.sylva.tree_hash
    bark.sylva.scale = 20
    assert bark.sylva.tree_hash != before
    bpy.ops.sylva.paste_share_link(link=link)
    assert bark.sylva.tree_hash == before


def sylva_hash(fixture):
    """The CLI's hash of a fixture's tree."""
    args = ["--preset", fixture["preset"]] if "preset" in fixture else []
    args += [a for k, v in fixture["values"].items() for a in ("--set", f"{k}={v}")]
    if "edits" in fixture:
        path = Path(_home) / "edits.json"
        path.write_text(json.dumps(fixture["edits"]))
        args += ["--edits", str(path)]
    return cli(*args)["hash"]


def render(path):
    """A small Workbench picture of the scene's trees (SYLVA_RENDER)."""
    scene = bpy.context.scene
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(camera)
    camera.location = (0, -34, 9)
    camera.rotation_euler = (1.45, 0, 0)
    scene.camera = camera
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
    scene.collection.objects.link(sun)
    sun.rotation_euler = (0.8, 0.2, 0.5)
    scene.render.engine = "BLENDER_EEVEE_NEXT"
    scene.render.resolution_x, scene.render.resolution_y = 480, 480
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)


def main():
    install()
    bark = test_add()
    print("add: objects, materials, textures, wind attributes, instances, hash: ok")
    test_a_change_regrows(bark)
    print("a parameter change regrows the tree (the CLI's hash): ok")
    test_share_links(bark)
    print("share links: the studio's links open the CLI's trees; copy and paste back: ok")
    if os.environ.get("SYLVA_RENDER"):
        bpy.ops.sylva.paste_share_link(link="v=1&seed=3")
        render(os.environ["SYLVA_RENDER"])


if __name__ == "__main__":
    main()
