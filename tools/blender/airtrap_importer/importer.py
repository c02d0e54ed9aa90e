# File ▸ Import ▸ Airtrap bake: the sequences of an export folder as objects that follow the
# frame (docs/BLENDER.md), in one collection named after the bake.
import os

import bpy

from . import bake_listing
from . import frame_picker
from . import materials
from . import ply_points

# The export's up axis → obj_import's axes, so that Blender's z is up either way.
OBJ_AXES = {"z": {"forward_axis": 'Y', "up_axis": 'Z'},
            "y": {"forward_axis": 'NEGATIVE_Z', "up_axis": 'Y'}}


class ImportReport:
    """What the import made and what it skipped, for the report area and the console."""

    def __init__(self):
        self.objects = {}
        self.warnings = []

    def warn(self, text):
        self.warnings.append(text)
        print("Airtrap import: " + text)


def _import_obj_frame(path, up_axis):
    """The objects of one OBJ file, imported unselected into no collection but the scene's."""
    before = set(bpy.data.objects)
    bpy.ops.wm.obj_import(filepath=path, **OBJ_AXES.get(up_axis, OBJ_AXES["y"]))
    return [obj for obj in bpy.data.objects if obj not in before]


def _frame_mesh(objects, name):
    """One mesh object from the objects of a frame's file (joined when there are several)."""
    for obj in objects:
        for collection in list(obj.users_collection):
            collection.objects.unlink(obj)
    if not objects:
        return bpy.data.objects.new(name, bpy.data.meshes.new(name))
    target = objects[0]
    if len(objects) > 1:
        with bpy.context.temp_override(active_object=target, selected_editable_objects=objects):
            bpy.ops.object.join()
    target.name = name
    target.data.name = name
    return target


def _import_sequence(sequence, name, parent, report, frame_object, spheres_material=None):
    """`sequence` as the object `name` following the frame: `frame_object(frame, path)` makes
    each frame's object (`path` None when its file is missing, which is reported: that frame shows
    nothing)."""
    present, missing = sequence.present_frames()
    for path in missing:
        report.warn("%s is missing: its frame is skipped" % path)
    first, last = sequence.frames[0], sequence.frames[-1]
    frames = frame_picker.hidden_collection(name + " frames", parent)
    for frame in range(first, last + 1):
        obj = frame_object(frame, sequence.path(frame) if frame in present else None)
        obj.name = frame_picker.frame_object_name(sequence.key.replace(".", "_"), frame)
        frames.objects.link(obj)
    return frame_picker.picking_object(name, parent, frames, first, "Airtrap " + name.lower(),
                                       spheres_material)


def import_mesh_sequence(sequence, name, parent, report, material=None, smooth=False):
    """`sequence` (OBJ) as a mesh object following the frame."""
    def frame_object(frame, path):
        objects = []
        if path is not None:
            try:
                objects = _import_obj_frame(path, sequence.up_axis)
            except RuntimeError as error:
                report.warn("%s cannot be read (%s): its frame is skipped"
                            % (path, str(error).strip()))
        obj = _frame_mesh(objects, "%s %d" % (name, frame))
        mesh = obj.data
        if smooth and mesh.polygons:
            mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
        if material is not None:
            mesh.materials.clear()
            mesh.materials.append(material)
        return obj

    return _import_sequence(sequence, name, parent, report, frame_object)


def _to_blender_axes(x, y, z, up_axis):
    """A point or vector of a Y-up export in Blender's Z-up axes (as obj_import turns OBJs)."""
    return (x, y, z) if up_axis == "z" else (x, -z, y)


def _points_object(columns, name, up_axis):
    """A mesh of bare points with the PLY's `pscale` and its `vx vy vz` as `velocity`."""
    mesh = bpy.data.meshes.new(name)
    count = len(columns.get("x", []))
    positions, velocities = [], []
    for i in range(count):
        positions.extend(_to_blender_axes(columns["x"][i], columns["y"][i], columns["z"][i],
                                          up_axis))
        if "vx" in columns:
            velocities.extend(_to_blender_axes(columns["vx"][i], columns["vy"][i],
                                               columns["vz"][i], up_axis))
    mesh.vertices.add(count)
    mesh.vertices.foreach_set("co", positions)
    if "pscale" in columns:
        mesh.attributes.new("pscale", 'FLOAT', 'POINT').data.foreach_set("value",
                                                                          columns["pscale"])
    if velocities:
        mesh.attributes.new("velocity", 'FLOAT_VECTOR', 'POINT').data.foreach_set(
            "vector", velocities)
    return bpy.data.objects.new(name, mesh)


def import_point_sequence(sequence, name, parent, report, material):
    """`sequence` (PLY points) as spheres of radius `pscale` following the frame."""
    def frame_object(frame, path):
        columns = {}
        if path is not None:
            try:
                columns = ply_points.read_points(path)
            except (OSError, ply_points.PlyError) as error:
                report.warn("%s: its frame is skipped" % error)
        return _points_object(columns, "%s %d" % (name, frame), sequence.up_axis)

    return _import_sequence(sequence, name, parent, report, frame_object,
                            spheres_material=material)


def import_bake(directory, context):
    """Imports the export folder `directory`; bake_listing.ListingError when it cannot."""
    listing = bake_listing.read_listing(directory)
    report = ImportReport()
    collection = bpy.data.collections.new(listing.scene_name)
    context.scene.collection.children.link(collection)

    water = listing.sequence("water.obj")
    if water is not None and water.frames:
        report.objects["water"] = import_mesh_sequence(
            water, "Water", collection, report, materials.water_material(), smooth=True)
    else:
        report.warn("%s has no water mesh sequence (water_####.obj): export with "
                    "`airtrap-cli export CACHE --format obj --up z`" % listing.directory)

    for key, name in (("bubbles.ply", "Bubbles"), ("subgrid.ply", "Sub-grid bubbles")):
        points = listing.sequence(key)
        if points is not None and points.frames:
            report.objects[name.lower()] = import_point_sequence(
                points, name, collection, report, materials.air_material())

    scene = context.scene
    scene.frame_start = listing.frame_start
    scene.frame_end = listing.frame_end
    scene.render.fps = max(1, int(round(listing.fps)))
    scene.render.fps_base = scene.render.fps / listing.fps if listing.fps > 0 else 1.0
    return report


def folder_of(path):
    """The folder the file browser points at, whether a file or the folder was chosen."""
    return path if os.path.isdir(path) else os.path.dirname(path)
