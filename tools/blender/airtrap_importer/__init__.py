# Airtrap bake importer for Blender: File ▸ Import ▸ Airtrap bake (docs/BLENDER.md).
bl_info = {
    "name": "Airtrap bake importer",
    "author": "Airtrap",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > Airtrap bake",
    "description": "Imports an Airtrap export folder: water, bubbles, volume and bodies "
                   "following the frame",
    "category": "Import-Export",
}

import bpy
from bpy.props import BoolProperty, EnumProperty, StringProperty
from bpy_extras.io_utils import ImportHelper

from . import bake_listing
from . import importer


class ImportAirtrapBake(bpy.types.Operator, ImportHelper):
    """Import the sequences of an Airtrap export folder"""
    bl_idname = "import_scene.airtrap_bake"
    bl_label = "Import Airtrap bake"
    bl_options = {'REGISTER', 'UNDO'}

    filename_ext = ""
    directory: StringProperty(subtype='DIR_PATH')
    filter_glob: StringProperty(default="export.json", options={'HIDDEN'})
    bubble_shape: EnumProperty(
        name="Bubbles",
        description="How the trapped bubbles are shown: spheres on the exported points, or the "
                    "oscillating ellipsoid meshes",
        items=(('SPHERES', "Spheres", "A sphere of the bubble's radius on every point of "
                "bubbles_####.ply, carrying its velocity for motion blur"),
               ('MESHES', "Oscillating meshes", "The ellipsoids of bubbles_####.obj, stretched "
                "along the velocity and wobbling after birth")),
        default='SPHERES')
    import_volume: BoolProperty(
        name="Volume", default=False,
        description="fluid_####.vdb as a volume sequence: the density grid as a light fog, the "
                    "velocity grid for motion blur")
    preview_scene: BoolProperty(
        name="Preview scene", default=True,
        description="A camera framing the bake, a sun, a sky, a floor, the tank as thin glass "
                    "and quick Cycles settings")

    def execute(self, context):
        try:
            folder = importer.folder_of(self.directory or self.filepath)
            report = importer.import_bake(folder, context, importer.ImportOptions(
                self.bubble_shape, self.import_volume, self.preview_scene))
        except bake_listing.ListingError as error:
            print("Airtrap import: %s" % error)
            self.report({'ERROR'}, str(error))
            return {'CANCELLED'}
        for warning in report.warnings:
            self.report({'WARNING'}, warning)
        for note in report.notes:
            self.report({'INFO'}, note)
        self.report({'INFO'}, "Airtrap bake imported: %s" % ", ".join(sorted(report.objects)))
        return {'FINISHED'}


def menu_entry(self, context):
    self.layout.operator(ImportAirtrapBake.bl_idname, text="Airtrap bake")


def register():
    bpy.utils.register_class(ImportAirtrapBake)
    bpy.types.TOPBAR_MT_file_import.append(menu_entry)


def unregister():
    bpy.types.TOPBAR_MT_file_import.remove(menu_entry)
    bpy.utils.unregister_class(ImportAirtrapBake)
