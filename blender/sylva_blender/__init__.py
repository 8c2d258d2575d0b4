"""Sylva Trees for Blender: *Add ▸ Mesh ▸ Sylva Tree* grows a tree with the Sylva core (the
bundled `sylva_trees` wheel): a bark object and an instanced leaves object with their
materials. The sidebar's *Sylva* tab edits the selected tree (every parameter of the registry)
and exchanges it with the studio as a share link. docs/blender.md describes it."""

import bpy

from . import operators, panel, settings


class SylvaPreferences(bpy.types.AddonPreferences):
    """Where the studio runs: the address a copied share link starts with."""

    bl_idname = __package__

    studio_url: bpy.props.StringProperty(
        name="Studio address",
        description="The Sylva studio's address: a copied share link is this address and the tree's query",
        default="http://localhost:5173/",
    )

    def draw(self, context):
        self.layout.prop(self, "studio_url")


def register():
    bpy.utils.register_class(SylvaPreferences)
    settings.register()
    operators.register()
    panel.register()


def unregister():
    panel.unregister()
    operators.unregister()
    settings.unregister()
    bpy.utils.unregister_class(SylvaPreferences)
