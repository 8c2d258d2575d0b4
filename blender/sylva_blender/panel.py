"""The sidebar's *Sylva* tab: the selected tree's preset, seed and hash, the share-link buttons,
and every parameter of the registry in the studio's groups (one collapsible section per group,
in the registry's order)."""

import bpy

from . import operators, settings

#: The registry's groups in panel order, each with its parameter ids.
GROUPS = {}
for _spec in settings.REGISTRY:
    GROUPS.setdefault(_spec["group"], []).append(_spec["id"])


class SYLVA_PT_tree(bpy.types.Panel):
    bl_label = "Sylva Tree"
    bl_idname = "SYLVA_PT_tree"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Sylva"

    def draw(self, context):
        layout = self.layout
        bark = operators.tree_of(context)
        if bark is None:
            layout.operator("mesh.sylva_tree_add", icon="ADD")
            layout.operator("sylva.paste_share_link", icon="PASTEDOWN")
            layout.label(text="Select a Sylva tree to edit it.")
            return
        s = bark.sylva
        layout.prop(s, "preset")
        row = layout.row(align=True)
        row.prop(s, "seed")
        row.operator("sylva.new_seed", text="", icon="FILE_REFRESH")
        row = layout.row(align=True)
        row.operator("sylva.copy_share_link", icon="COPYDOWN")
        row.operator("sylva.paste_share_link", icon="PASTEDOWN")
        layout.label(text=f"Hash {s.tree_hash}")
        if s.edits_json not in ("", "[]") or s.volumes_json not in ("", "[]"):
            layout.label(text="Hand edits or growth primitives from a link", icon="INFO")
        for group, ids in GROUPS.items():
            header, body = layout.panel(f"SYLVA_group_{group}", default_closed=group != "Tree")
            header.label(text=group)
            if body is not None:
                for key in ids:
                    if key != "seed":
                        body.prop(s, key)


def register():
    bpy.utils.register_class(SYLVA_PT_tree)


def unregister():
    bpy.utils.unregister_class(SYLVA_PT_tree)
