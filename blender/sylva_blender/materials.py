"""The tree's materials: bark, cut face and leaves, each a Principled BSDF over the core's
textures (colour and tangent-space normal map); the leaf colour is the texture times each
leaf's tint, read from its instance (`leaf_color`), and its alpha cuts the leaf's outline."""

import bpy

#: The bark object's material slots, in the order of the core's material names.
SLOTS = ("bark", "cut_face")


def _principled(name):
    """A material named `name` with a fresh node tree: Principled BSDF to the output."""
    material = bpy.data.materials.get(name) or bpy.data.materials.new(name)
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    bsdf = nodes.new("ShaderNodeBsdfPrincipled")
    bsdf.location = (-300, 0)
    material.node_tree.links.new(bsdf.outputs["BSDF"], output.inputs["Surface"])
    return material, bsdf


def _image(material, image, x, y):
    node = material.node_tree.nodes.new("ShaderNodeTexImage")
    node.image = image
    node.location = (x, y)
    return node


def _normal_map(material, bsdf, image):
    links = material.node_tree.links
    texture = _image(material, image, -1000, -300)
    normal = material.node_tree.nodes.new("ShaderNodeNormalMap")
    normal.location = (-600, -300)
    links.new(texture.outputs["Color"], normal.inputs["Color"])
    links.new(normal.outputs["Normal"], bsdf.inputs["Normal"])


def _textured(name, images, prefix, roughness):
    """A material over the `prefix`_color and `prefix`_normal images."""
    material, bsdf = _principled(name)
    links = material.node_tree.links
    color = _image(material, images[f"{prefix}_color"], -1000, 200)
    links.new(color.outputs["Color"], bsdf.inputs["Base Color"])
    links.new(color.outputs["Alpha"], bsdf.inputs["Alpha"])
    _normal_map(material, bsdf, images[f"{prefix}_normal"])
    bsdf.inputs["Roughness"].default_value = roughness
    return material


def _forget(images):
    for image in list(images):
        if image is not None and image.users == 0:
            bpy.data.images.remove(image)


def _old_images(material):
    if material is None or not material.use_nodes:
        return []
    return [n.image for n in material.node_tree.nodes if n.type == "TEX_IMAGE"]


def assign(bark, name, images):
    """Bark and cut-face materials on the bark object's slots."""
    old = [img for slot in SLOTS for img in _old_images(bpy.data.materials.get(f"{name} {slot}"))]
    made = [
        _textured(f"{name} bark", images, "bark", 0.85),
        _textured(f"{name} cut_face", images, "cut_face", 0.7),
    ]
    mesh = bark.data
    mesh.materials.clear()
    for material in made:
        mesh.materials.append(material)
    _forget(old)


def assign_leaf(shape, name, images):
    """The leaf material on the leaf shape: texture times the instance's tint, alpha-cut."""
    material_name = f"{name} leaves"
    old = _old_images(bpy.data.materials.get(material_name))
    shape.data.materials.clear()
    if "leaf_color" not in images:
        _forget(old)
        return
    material, bsdf = _principled(material_name)
    nodes, links = material.node_tree.nodes, material.node_tree.links
    color = _image(material, images["leaf_color"], -1200, 200)
    tint = nodes.new("ShaderNodeAttribute")
    tint.attribute_type = "INSTANCER"
    tint.attribute_name = "leaf_color"
    tint.location = (-1200, 450)
    multiply = nodes.new("ShaderNodeMix")
    multiply.data_type = "RGBA"
    multiply.blend_type = "MULTIPLY"
    multiply.inputs["Factor"].default_value = 1.0
    multiply.location = (-800, 300)
    # The colour sockets of the Mix node (its float and vector sockets share the names).
    links.new(color.outputs["Color"], multiply.inputs[6])
    links.new(tint.outputs["Color"], multiply.inputs[7])
    links.new(multiply.outputs[2], bsdf.inputs["Base Color"])
    links.new(color.outputs["Alpha"], bsdf.inputs["Alpha"])
    _normal_map(material, bsdf, images["leaf_normal"])
    bsdf.inputs["Roughness"].default_value = 0.6
    material.use_backface_culling = False
    shape.data.materials.append(material)
    _forget(old)
