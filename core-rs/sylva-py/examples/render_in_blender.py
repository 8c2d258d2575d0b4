"""A tree made in Python, rendered in Blender: the picture in docs/python.md.

Run with a Python that has both `sylva_trees` (the wheel) and `bpy` (Blender as a module):

    python core-rs/sylva-py/examples/render_in_blender.py oak 3 docs/img/python-oak.png

It generates the preset with `sylva_trees`, writes a GLB with the leaves merged (the form
editors take), imports it into an empty Blender scene, frames it and renders with Workbench.
"""

import sys
import tempfile
from pathlib import Path

import bpy
import mathutils
import sylva_trees


def main(preset: str, seed: int, out: str) -> None:
    tree = sylva_trees.generate(preset=preset, seed=seed)
    glb = Path(tempfile.mkdtemp()) / f"{preset}.glb"
    tree.to_glb(str(glb), leaves="baked")
    print(f"{preset} seed {seed}: hash {tree.hash}")

    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=str(glb))
    scene = bpy.context.scene
    corners = [
        o.matrix_world @ mathutils.Vector(c) for o in scene.objects if o.type == "MESH" for c in o.bound_box
    ]
    lo = mathutils.Vector([min(c[k] for c in corners) for k in range(3)])
    hi = mathutils.Vector([max(c[k] for c in corners) for k in range(3)])
    centre, size = (lo + hi) / 2, max(hi - lo)

    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(camera)
    camera.location = centre + mathutils.Vector((size * 1.1, -size * 1.1, size * 0.25))
    camera.rotation_euler = (centre - camera.location).to_track_quat("-Z", "Y").to_euler()
    scene.camera = camera
    world = bpy.data.worlds.new("sky")
    world.color = (0.75, 0.82, 0.9)
    scene.world = world

    scene.render.engine = "BLENDER_WORKBENCH"
    scene.display.shading.light = "STUDIO"
    scene.display.shading.color_type = "TEXTURE"
    scene.render.resolution_x = scene.render.resolution_y = 480
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]), sys.argv[3])
