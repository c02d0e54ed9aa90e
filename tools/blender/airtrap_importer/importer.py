# File ▸ Import ▸ Airtrap bake: the sequences of an export folder as objects that follow the
# frame (docs/BLENDER.md), in one collection named after the bake.
import os

import bpy
from mathutils import Matrix

from . import bake_listing
from . import frame_picker
from . import materials
from . import obj_trailer
from . import ply_points
from . import preview_scene
from . import volume_sequence

# The export's up axis → obj_import's axes, so that Blender's z is up either way.
OBJ_AXES = {"z": {"forward_axis": 'Y', "up_axis": 'Z'},
            "y": {"forward_axis": 'NEGATIVE_Z', "up_axis": 'Y'}}


class ImportReport:
    """What the import made and what it skipped, for the report area and the console."""

    def __init__(self):
        self.objects = {}
        self.warnings = []
        # What the import did besides making objects, said as information.
        self.notes = []
        # The hidden collections holding each sequence's per-frame objects.
        self.frame_collections = []

    def warn(self, text):
        self.warnings.append(text)
        print("Airtrap import: " + text)


def _import_obj_frame(path, up_axis):
    """The objects of one OBJ file, imported unselected into no collection but the scene's."""
    before = set(bpy.data.objects)
    bpy.ops.wm.obj_import(filepath=path, **OBJ_AXES.get(up_axis, OBJ_AXES["y"]))
    return [obj for obj in bpy.data.objects if obj not in before]


def _read_obj_frame(path, up_axis, report):
    """The objects of a whole OBJ frame; none, with a warning, for a file cut short or
    unreadable."""
    try:
        promised = obj_trailer.triangle_count(path)
        objects = _import_obj_frame(path, up_axis)
    except (OSError, RuntimeError, obj_trailer.ObjCutShort) as error:
        report.warn("%s: its frame is skipped" % str(error).strip())
        return []
    read = sum(len(obj.data.polygons) for obj in objects if obj.type == 'MESH')
    if read != promised:
        report.warn("%s holds %d triangles where its last line says %d: its frame shows the %d "
                    "read" % (path, read, promised, read))
    return objects


def _frame_mesh(objects, name):
    """One mesh object from the objects of a frame's file (joined when there are several)."""
    for obj in objects:
        for collection in list(obj.users_collection):
            collection.objects.unlink(obj)
        # The OBJ importer turns a Y-up file by the object's rotation; the frame picker resets
        # its children's transforms, so the turn goes into the mesh itself.
        obj.data.transform(obj.matrix_world)
        obj.matrix_world = Matrix.Identity(4)
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
    each frame's object (`path` None when its file is missing or damaged, which is reported: that
    frame shows nothing)."""
    present, _, warnings = sequence.usable_frames()
    for warning in warnings:
        report.warn(warning)
    first, last = sequence.frames[0], sequence.frames[-1]
    frames = frame_picker.hidden_collection(name + " frames", parent)
    report.frame_collections.append(frames)
    for frame in range(first, last + 1):
        obj = frame_object(frame, sequence.path(frame) if frame in present else None)
        obj.name = frame_picker.frame_object_name(sequence.key.replace(".", "_"), frame)
        frames.objects.link(obj)
    return frame_picker.picking_object(name, parent, frames, first, "Airtrap " + name.lower(),
                                       spheres_material)


def import_mesh_sequence(sequence, name, parent, report, material=None, smooth=False):
    """`sequence` (OBJ) as a mesh object following the frame."""
    def frame_object(frame, path):
        objects = _read_obj_frame(path, sequence.up_axis, report) if path is not None else []
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
        if all(name in columns for name in ("vx", "vy", "vz")):
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


class ImportOptions:
    """What the import dialog offers: the trapped bubbles as `bubble_shape` 'SPHERES' (from the
    PLY points) or 'MESHES' (the oscillating ellipsoids of the OBJ), the volume sequence or not,
    and a preview scene (camera, sun, sky, floor, Cycles settings) or not."""

    def __init__(self, bubble_shape='SPHERES', volume=False, preview=True):
        self.bubble_shape = bubble_shape
        self.volume = volume
        self.preview = preview


def _present(listing, key):
    sequence = listing.sequence(key)
    return sequence if sequence is not None and sequence.frames else None


def _present_or_said(listing, key, what, report):
    """The sequence `key` ("water.obj"), or None with a warning saying how to export it."""
    sequence = _present(listing, key)
    if sequence is None:
        stem, _, ext = key.rpartition(".")
        report.warn("%s has no %s (%s_####.%s): export with `airtrap-cli export CACHE --format "
                    "%s --up z`" % (listing.directory, what, stem, ext, ext))
    return sequence


def _import_water(listing, collection, report):
    water = _present_or_said(listing, "water.obj", "water mesh sequence", report)
    if water is not None:
        report.objects["water"] = import_mesh_sequence(
            water, "Water", collection, report, materials.water_material(), smooth=True)


def _readable(sequence):
    """`sequence` when at least one of its files is there and whole, else None."""
    return sequence if sequence is not None and sequence.usable_frames()[0] else None


def _import_bubbles(listing, collection, report, bubble_shape):
    """The trapped bubbles in the shape asked for, or in the other when only it was exported
    (or only its files are there)."""
    points, meshes = _present(listing, "bubbles.ply"), _present(listing, "bubbles.obj")
    if points is not None and meshes is not None:
        readable_points, readable_meshes = _readable(points), _readable(meshes)
        if readable_points is None and readable_meshes is not None:
            points = None
        elif readable_meshes is None and readable_points is not None:
            meshes = None
    if bubble_shape == 'MESHES' and meshes is None and points is not None:
        report.warn("%s has no bubble meshes (bubbles_####.obj): the bubbles are spheres from "
                    "bubbles_####.ply" % listing.directory)
    if bubble_shape == 'SPHERES' and points is None and meshes is not None:
        report.warn("%s has no bubble points (bubbles_####.ply): the bubbles are the meshes of "
                    "bubbles_####.obj" % listing.directory)
    if meshes is not None and (bubble_shape == 'MESHES' or points is None):
        report.objects["bubbles"] = import_mesh_sequence(
            meshes, "Bubbles", collection, report, materials.air_material(), smooth=True)
    elif points is not None:
        report.objects["bubbles"] = import_point_sequence(
            points, "Bubbles", collection, report, materials.air_material())
    subgrid = _present(listing, "subgrid.ply")
    if subgrid is not None:
        report.objects["sub-grid bubbles"] = import_point_sequence(
            subgrid, "Sub-grid bubbles", collection, report, materials.air_material())


def _import_volume(listing, collection, report):
    fluid = _present_or_said(listing, "fluid.vdb", "volume sequence", report)
    volume = None if fluid is None else volume_sequence.import_volume_sequence(
        fluid, "Water volume", collection, report)
    if volume is not None:
        report.objects["water volume"] = volume


def _set_frames(scene, listing):
    scene.frame_start = listing.frame_start
    scene.frame_end = listing.frame_end
    scene.frame_current = listing.frame_start
    scene.render.fps = max(1, int(round(listing.fps)))
    scene.render.fps_base = scene.render.fps / listing.fps if listing.fps > 0 else 1.0


def import_bake(directory, context, options=None):
    """Imports the export folder `directory`; bake_listing.ListingError when it cannot."""
    options = options or ImportOptions()
    listing = bake_listing.read_listing(directory)
    report = ImportReport()
    startup = preview_scene.untouched_startup_objects(context.scene) if options.preview else []
    for warning in listing.warnings:
        report.warn(warning)
    collection = bpy.data.collections.new(listing.scene_name)
    context.scene.collection.children.link(collection)

    _import_water(listing, collection, report)
    _import_bubbles(listing, collection, report, options.bubble_shape)
    bodies = _present(listing, "bodies.obj")
    if bodies is not None:
        report.objects["bodies"] = import_mesh_sequence(bodies, "Bodies", collection, report,
                                                        materials.body_material())
    if options.volume:
        _import_volume(listing, collection, report)
    _set_frames(context.scene, listing)
    if options.preview:
        preview = preview_scene.set_up(context.scene, collection, report.frame_collections,
                                       listing.container)
        if preview is not None and startup:
            preview_scene.remove_startup_objects(startup)
            report.notes.append("Blender's startup cube, light and camera removed: the preview "
                                "scene frames and lights the bake")
    _make_active(context, report)
    return report


def _make_active(context, report):
    """The object an artist edits next is the water (or the first object made), not the hidden
    frame object the OBJ importer left active and selected."""
    for obj in context.view_layer.objects:
        obj.select_set(False)
    made = [report.objects[key] for key in ("water", "bubbles", "bodies", "water volume")
            if key in report.objects]
    if made:
        context.view_layer.objects.active = made[0]
        made[0].select_set(True)


def folder_of(path):
    """The folder the file browser points at, whether a file or the folder was chosen."""
    if not path:
        raise bake_listing.ListingError("no folder chosen: choose an export folder (the one "
                                        "holding export.json)")
    if os.path.isfile(path):
        return os.path.dirname(path)
    # A folder, or a path that is not there: read_listing says which.
    return path
