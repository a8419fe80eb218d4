"""scaf UV: bijective unwrap, pack and check for Blender, with scaf.

A Blender add-on (package scaf_uv) over the scaf Python package (a
ctypes binding of libscaf). Three operators on the active UV map of the
selected mesh objects, in the UV editor's UV menu and sidebar tab "scaf"
and in the 3D view's UV menu (edit mode):
  - Bijective Unwrap: islands cut along the marked seams, no flipped or
    overlapping triangle, packed with a certified padding;
  - Bijective Pack: the current islands packed with a certified padding
    (from the current layout when it is bijective);
  - Check Bijectivity: the exact verdict, the bad faces selected.
How the scaf package is found: scaf_uv.library. Install: make the zip
with integrations/blender/make_zip.py, then Preferences > Add-ons >
Install... and enable "UV: scaf UV".
"""

bl_info = {
    "name": "scaf UV",
    "author": "the scaf project",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "UV Editor > UV menu and sidebar (N) > scaf; 3D View > UV menu (edit mode)",
    "description": "Bijective unwrap, pack and check of UV maps with scaf (no flipped or overlapping "
                   "triangle, certified padding)",
    "category": "UV",
}

import bpy  # noqa: E402

from . import operators  # noqa: E402


class ScafUVPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    package_dir: bpy.props.StringProperty(
        name="scaf package folder", subtype="DIR_PATH",
        description="Folder containing the Python package scaf (e.g. a checkout's python/); "
                    "empty: the scaf that Blender's Python imports (pip install)")
    library: bpy.props.StringProperty(
        name="libscaf library", subtype="FILE_PATH",
        description="libscaf.so to load (exported as SCAF_LIBRARY); empty: the package finds its own")
    program: bpy.props.StringProperty(
        name="scaf program", subtype="FILE_PATH",
        description="The scaf program Check runs (scaf check); empty: scaf on PATH, or beside libscaf")

    def draw(self, context):
        col = self.layout.column()
        col.prop(self, "package_dir")
        col.prop(self, "library")
        col.prop(self, "program")
        col.label(text="Changes apply after restarting Blender.")


class ScafUVSettings(bpy.types.PropertyGroup):
    resolution: bpy.props.IntProperty(name="Texture size", default=1024, min=1, max=65536,
                                      description="Texels per side of the texture")
    padding_texels: bpy.props.FloatProperty(name="Padding (texels)", default=4.0, min=0.0, max=1024.0,
                                            description="Smallest distance between two islands, in texels")


def _buttons(layout, context):
    s = context.scene.scaf_uv
    for idname in ("uv.scaf_bijective_unwrap", "uv.scaf_bijective_pack"):
        op = layout.operator(idname)
        op.resolution = s.resolution
        op.padding_texels = s.padding_texels
    layout.operator("uv.scaf_check")


class SCAF_PT_uv_panel(bpy.types.Panel):
    bl_label = "scaf: bijective UVs"
    bl_space_type = "IMAGE_EDITOR"
    bl_region_type = "UI"
    bl_category = "scaf"

    @classmethod
    def poll(cls, context):
        return context.space_data.mode == "UV" or context.mode == "EDIT_MESH"

    def draw(self, context):
        col = self.layout.column(align=True)
        s = context.scene.scaf_uv
        col.prop(s, "resolution")
        col.prop(s, "padding_texels")
        col.separator()
        _buttons(col, context)


def _menu(self, context):
    self.layout.separator()
    _buttons(self.layout, context)


classes = (ScafUVPreferences, ScafUVSettings, SCAF_PT_uv_panel) + operators.classes


def register():
    for c in classes:
        bpy.utils.register_class(c)
    bpy.types.Scene.scaf_uv = bpy.props.PointerProperty(type=ScafUVSettings)
    bpy.types.IMAGE_MT_uvs.append(_menu)
    bpy.types.VIEW3D_MT_uv_map.append(_menu)


def unregister():
    bpy.types.VIEW3D_MT_uv_map.remove(_menu)
    bpy.types.IMAGE_MT_uvs.remove(_menu)
    del bpy.types.Scene.scaf_uv
    for c in reversed(classes):
        bpy.utils.unregister_class(c)
