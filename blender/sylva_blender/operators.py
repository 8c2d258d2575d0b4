"""The operators: *Add ▸ Mesh ▸ Sylva Tree* (`mesh.sylva_tree_add`), a new seed, and the share
links (`sylva.copy_share_link`, `sylva.paste_share_link`) that exchange the exact tree with the
studio through the core's codec."""

import json
import random

import bpy
import sylva_trees

from . import build, settings


def tree_of(context):
    """The Sylva tree the selection belongs to (its bark object), or None."""
    obj = context.active_object
    while obj is not None and not obj.sylva.is_tree:
        obj = obj.parent
    return obj


class SYLVA_OT_tree_add(bpy.types.Operator):
    """Grow a Sylva tree: a bark object and its instanced leaves"""

    bl_idname = "mesh.sylva_tree_add"
    bl_label = "Sylva Tree"
    bl_options = {"REGISTER", "UNDO"}

    preset: bpy.props.EnumProperty(
        name="Preset", items=[(p["name"], p["label"], p["description"]) for p in settings.PRESETS]
    )
    seed: bpy.props.IntProperty(name="Seed", default=1, min=0, max=settings.INT_MAX)

    def execute(self, context):
        mesh = bpy.data.meshes.new("Sylva Tree")
        bark = bpy.data.objects.new("Sylva Tree", mesh)
        context.collection.objects.link(bark)
        bark.location = context.scene.cursor.location
        s = bark.sylva
        values = settings.preset_values(self.preset)
        values["seed"] = self.seed
        settings._quiet[0] = True
        try:
            s.is_tree = True
            s.preset = self.preset
        finally:
            settings._quiet[0] = False
        settings.set_values(s, values)
        try:
            tree = build.regenerate(bark)
        except ValueError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        for obj in context.selected_objects:
            obj.select_set(False)
        bark.select_set(True)
        context.view_layer.objects.active = bark
        self.report({"INFO"}, f"Sylva tree {tree.hash}: {len(tree.positions)} vertices, {len(tree.leaf_colors)} leaves")
        return {"FINISHED"}


class SYLVA_OT_new_seed(bpy.types.Operator):
    """Give the selected tree a random seed"""

    bl_idname = "sylva.new_seed"
    bl_label = "New Seed"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        bark = tree_of(context)
        if bark is None:
            return {"CANCELLED"}
        bark.sylva.seed = str(random.randrange(0, int(settings.BY_ID["seed"]["max"]) + 1))
        return {"FINISHED"}


class SYLVA_OT_copy_share_link(bpy.types.Operator):
    """Copy the selected tree's share link: the studio opens it as the same tree"""

    bl_idname = "sylva.copy_share_link"
    bl_label = "Copy Share Link"

    def execute(self, context):
        bark = tree_of(context)
        if bark is None:
            return {"CANCELLED"}
        volumes, edits = settings.structured(bark.sylva)
        query = sylva_trees.share_link(
            params=settings.values(bark.sylva), volumes=volumes or None, edits=edits or None
        )
        base = context.preferences.addons[__package__].preferences.studio_url
        link = f"{base.split('?')[0]}?{query}"
        context.window_manager.clipboard = link
        bark["sylva_share_link"] = link
        self.report({"INFO"}, "Share link copied")
        return {"FINISHED"}


class SYLVA_OT_paste_share_link(bpy.types.Operator):
    """Set the selected tree (or a new one) to the share link on the clipboard"""

    bl_idname = "sylva.paste_share_link"
    bl_label = "Paste Share Link"
    bl_options = {"REGISTER", "UNDO"}

    link: bpy.props.StringProperty(name="Link", description="The link; empty: the clipboard's")

    def execute(self, context):
        link = self.link or context.window_manager.clipboard
        if "v=" not in link:
            self.report({"ERROR"}, "No share link on the clipboard")
            return {"CANCELLED"}
        bark = tree_of(context)
        if bark is None:
            bpy.ops.mesh.sylva_tree_add()
            bark = context.active_object
        read = sylva_trees.read_share_link(link)
        s = bark.sylva
        settings._quiet[0] = True
        try:
            s.preset = "CUSTOM"
            s.volumes_json = json.dumps(read["volumes"])
            s.edits_json = json.dumps(read["edits"])
        finally:
            settings._quiet[0] = False
        settings.set_values(s, read["params"])
        build.regenerate(bark)
        for message in read["messages"]:
            self.report({"WARNING"}, message)
        return {"FINISHED"}


def _menu(self, context):
    self.layout.operator(SYLVA_OT_tree_add.bl_idname, text="Sylva Tree", icon="OUTLINER_OB_FORCE_FIELD")


CLASSES = (SYLVA_OT_tree_add, SYLVA_OT_new_seed, SYLVA_OT_copy_share_link, SYLVA_OT_paste_share_link)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.VIEW3D_MT_mesh_add.append(_menu)


def unregister():
    bpy.types.VIEW3D_MT_mesh_add.remove(_menu)
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
