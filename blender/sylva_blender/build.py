"""A Sylva tree in Blender objects: the bark mesh (custom normals, UVs, one material slot per
core material, the wind records as attributes), the leaf shape and a leaves object whose points
carry each leaf's place, rotation, scale and tint and instance the leaf shape with Geometry
Nodes (one object for every leaf). The core is y-up, Blender z-up: (x, y, z) -> (x, -z, y)."""

import os
import tempfile

import bpy
import numpy as np
import sylva_trees

from . import materials, settings

#: The core's y-up tree space to Blender's z-up space.
Y_UP_TO_Z_UP = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], dtype=np.float64)
#: The wind record's components as mesh attributes: (name, columns, type).
WIND = (
    ("wind_pivot", slice(0, 3), "FLOAT_VECTOR"),
    ("wind_level", 3, "FLOAT"),
    ("wind_phase", 4, "FLOAT"),
    ("wind_stiffness", 5, "FLOAT"),
    ("wind_distance", 6, "FLOAT"),
    ("wind_radius", 7, "FLOAT"),
)
NODE_GROUP = "Sylva Leaf Instances"


def z_up(points):
    """Rows of y-up points or directions as z-up ones."""
    return np.ascontiguousarray(points @ Y_UP_TO_Z_UP.T, dtype=np.float32)


def fill_mesh(mesh, positions, normals, uvs, indices):
    """Triangles into an empty mesh: vertices, loops, faces, UVs (v measured up, as Blender
    reads images) and the core's normals as custom normals."""
    mesh.vertices.add(len(positions))
    mesh.vertices.foreach_set("co", positions.ravel())
    flat = indices.ravel()
    mesh.loops.add(len(flat))
    mesh.loops.foreach_set("vertex_index", flat)
    mesh.polygons.add(len(indices))
    mesh.polygons.foreach_set("loop_start", np.arange(0, len(flat), 3, dtype=np.int32))
    mesh.update(calc_edges=True)
    uv = np.array(uvs[flat], dtype=np.float32)
    uv[:, 1] = 1.0 - uv[:, 1]
    mesh.uv_layers.new(name="UVMap").data.foreach_set("uv", uv.ravel())
    mesh.normals_split_custom_set_from_vertices(normals)


def bark_mesh(tree, name):
    """The bark: one material slot per core material group, the wind records as attributes."""
    mesh = bpy.data.meshes.new(name)
    fill_mesh(mesh, z_up(tree.positions), z_up(tree.normals), tree.uvs, tree.indices)
    slots = np.zeros(len(tree.indices), dtype=np.int32)
    for group in tree.meta["groups"]:
        slot = materials.SLOTS.index(group["material"]) if group["material"] in materials.SLOTS else 0
        slots[group["start"] // 3 : (group["start"] + group["count"]) // 3] = slot
    mesh.polygons.foreach_set("material_index", slots)
    wind = tree.wind
    if len(wind):
        for attribute, columns, kind in WIND:
            data = z_up(wind[:, columns]) if kind == "FLOAT_VECTOR" else np.ascontiguousarray(wind[:, columns])
            mesh.attributes.new(attribute, kind, "POINT").data.foreach_set(
                "vector" if kind == "FLOAT_VECTOR" else "value", data.ravel()
            )
    return mesh


def quaternions(rotations):
    """Unit quaternions (w, x, y, z) of rotation matrices `(n, 3, 3)`."""
    m = rotations
    w = np.sqrt(np.maximum(0.0, 1.0 + m[:, 0, 0] + m[:, 1, 1] + m[:, 2, 2])) / 2
    x = np.sqrt(np.maximum(0.0, 1.0 + m[:, 0, 0] - m[:, 1, 1] - m[:, 2, 2])) / 2
    y = np.sqrt(np.maximum(0.0, 1.0 - m[:, 0, 0] + m[:, 1, 1] - m[:, 2, 2])) / 2
    z = np.sqrt(np.maximum(0.0, 1.0 - m[:, 0, 0] - m[:, 1, 1] + m[:, 2, 2])) / 2
    x = np.copysign(x, m[:, 2, 1] - m[:, 1, 2])
    y = np.copysign(y, m[:, 0, 2] - m[:, 2, 0])
    z = np.copysign(z, m[:, 1, 0] - m[:, 0, 1])
    q = np.stack([w, x, y, z], axis=1)
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def leaf_points(tree, name):
    """One point per leaf with its rotation, scale and tint: the leaf transforms (column axes
    at right angles, as the core makes them) split into place, rotation and scale, in z-up."""
    m = tree.leaf_transforms.astype(np.float64)
    axes = np.einsum("ij,njk->nik", Y_UP_TO_Z_UP, m[:, :3, :3])
    scale = np.linalg.norm(axes, axis=1)
    mirrored = np.linalg.det(axes) < 0
    scale[mirrored, 0] *= -1
    rotation = axes / np.where(scale == 0, 1, scale)[:, None, :]
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(m))
    mesh.vertices.foreach_set("co", z_up(m[:, :3, 3]).ravel())
    mesh.attributes.new("leaf_rotation", "QUATERNION", "POINT").data.foreach_set(
        "value", quaternions(rotation).astype(np.float32).ravel()
    )
    mesh.attributes.new("leaf_scale", "FLOAT_VECTOR", "POINT").data.foreach_set(
        "vector", scale.astype(np.float32).ravel()
    )
    tint = np.ones((len(m), 4), dtype=np.float32)
    tint[:, :3] = tree.leaf_colors
    mesh.attributes.new("leaf_color", "FLOAT_COLOR", "POINT").data.foreach_set("color", tint.ravel())
    return mesh


def instancing_group():
    """Geometry Nodes: instance the object in the modifier's input on every point, placed by the
    points' `leaf_rotation` and `leaf_scale` (the tint travels to the instances as `leaf_color`)."""
    group = bpy.data.node_groups.get(NODE_GROUP)
    if group is not None:
        return group
    group = bpy.data.node_groups.new(NODE_GROUP, "GeometryNodeTree")
    group.interface.new_socket("Geometry", in_out="INPUT", socket_type="NodeSocketGeometry")
    group.interface.new_socket("Leaf", in_out="INPUT", socket_type="NodeSocketObject")
    group.interface.new_socket("Geometry", in_out="OUTPUT", socket_type="NodeSocketGeometry")
    nodes, links = group.nodes, group.links
    inputs, outputs = nodes.new("NodeGroupInput"), nodes.new("NodeGroupOutput")
    info = nodes.new("GeometryNodeObjectInfo")
    info.transform_space = "ORIGINAL"
    instance = nodes.new("GeometryNodeInstanceOnPoints")
    rotation = nodes.new("GeometryNodeInputNamedAttribute")
    rotation.data_type = "QUATERNION"
    rotation.inputs["Name"].default_value = "leaf_rotation"
    scale = nodes.new("GeometryNodeInputNamedAttribute")
    scale.data_type = "FLOAT_VECTOR"
    scale.inputs["Name"].default_value = "leaf_scale"
    links.new(inputs.outputs[1], info.inputs["Object"])
    links.new(inputs.outputs[0], instance.inputs["Points"])
    links.new(info.outputs["Geometry"], instance.inputs["Instance"])
    links.new(rotation.outputs["Attribute"], instance.inputs["Rotation"])
    links.new(scale.outputs["Attribute"], instance.inputs["Scale"])
    links.new(instance.outputs["Instances"], outputs.inputs[0])
    return group


def _replace_mesh(obj, mesh):
    old = obj.data
    obj.data = mesh
    if old is not None and old.users == 0:
        bpy.data.meshes.remove(old)


def _child(bark, settings_slot, name, mesh):
    """The child object kept in `bark.sylva.<settings_slot>`, made or given `mesh`."""
    obj = getattr(bark.sylva, settings_slot)
    if obj is None or obj.name not in bpy.data.objects:
        obj = bpy.data.objects.new(name, mesh)
        for collection in bark.users_collection:
            collection.objects.link(obj)
        obj.parent = bark
        settings._quiet[0] = True
        try:
            setattr(bark.sylva, settings_slot, obj)
        finally:
            settings._quiet[0] = False
    else:
        _replace_mesh(obj, mesh)
    return obj


def load_textures(tree, name):
    """The tree's PNG textures as packed images, by name (`bark_color`, ...)."""
    images = {}
    with tempfile.TemporaryDirectory() as folder:
        for key, png in tree.textures().items():
            path = os.path.join(folder, f"{name}_{key}.png")
            with open(path, "wb") as f:
                f.write(png)
            image = bpy.data.images.load(path)
            image.pack()
            image.name = f"{name} {key}"
            if key.endswith("normal"):
                image.colorspace_settings.name = "Non-Color"
            images[key] = image
    return images


def regenerate(bark):
    """Grows the tree `bark.sylva` describes and puts it into `bark`, its leaf shape and its
    leaves object. Returns the tree."""
    s = bark.sylva
    volumes, edits = settings.structured(s)
    tree = sylva_trees.generate(params=settings.values(s), volumes=volumes or None, edits=edits or None)
    name = bark.name
    _replace_mesh(bark, bark_mesh(tree, f"{name} bark"))
    images = load_textures(tree, name)
    materials.assign(bark, name, images)
    shape_mesh = bpy.data.meshes.new(f"{name} leaf")
    if len(tree.leaf_indices):
        fill_mesh(shape_mesh, tree.leaf_positions, tree.leaf_normals, tree.leaf_uvs, tree.leaf_indices)
    shape = _child(bark, "leaf_shape_object", f"{name} leaf", shape_mesh)
    shape.hide_set(True)
    shape.hide_render = True
    leaves = _child(bark, "leaves_object", f"{name} leaves", leaf_points(tree, f"{name} leaves"))
    modifier = leaves.modifiers.get("Sylva leaves") or leaves.modifiers.new("Sylva leaves", "NODES")
    modifier.node_group = instancing_group()
    leaf_input = next(
        item
        for item in modifier.node_group.interface.items_tree
        if item.item_type == "SOCKET" and item.in_out == "INPUT" and item.name == "Leaf"
    )
    modifier[leaf_input.identifier] = shape
    materials.assign_leaf(shape, name, images)
    settings._quiet[0] = True
    try:
        s.tree_hash = tree.hash
    finally:
        settings._quiet[0] = False
    return tree
