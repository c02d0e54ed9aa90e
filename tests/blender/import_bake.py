# Run by ctest (label blender) as
#   blender -b --factory-startup --python import_bake.py -- EXPORT_DIR WORK_DIR BODIES_EXPORT_DIR \
#       Y_UP_EXPORT_DIR
# The add-on enables; the default import makes a Water object whose mesh at the first and last
# frames has exactly the vertices and faces of water_000N.obj, Bubbles whose spheres are the
# points of bubbles_000N.ply with their pscale as radius and their velocity on every vertex, and
# a preview scene; saved, the file plays the water in a fresh Blender without the add-on. With
# the other options the bubbles are the meshes of bubbles_000N.obj and the volume has the
# density grid; the buoyancy export gives Bodies with the counts of bodies_000N.obj; the same bake
# exported Y up lands where the Z-up export does (water, bubbles, volume, camera). Exits non-zero
# on the first failure, naming it.
import math
import os
import subprocess
import sys
from array import array

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "blender"))

import addon_utils  # noqa: E402 (the add-on's folder goes on the path first)
import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402

from airtrap_importer import ply_points  # noqa: E402

export_dir, work_dir, bodies_dir, y_up_dir = (os.path.abspath(a)
                                              for a in sys.argv[sys.argv.index("--") + 1:][:4])
SPHERE_VERTICES = 42  # an icosphere of two subdivisions


def fail(text):
    print("FAIL: " + text)
    sys.exit(1)


def obj_counts(path):
    vertices = faces = 0
    with open(path, "r", encoding="utf-8") as file:
        for line in file:
            if line.startswith("v "):
                vertices += 1
            elif line.startswith("f "):
                faces += 1
    return vertices, faces


def evaluated_mesh(obj, frame):
    bpy.context.scene.frame_set(frame)
    return obj.evaluated_get(bpy.context.evaluated_depsgraph_get()).data


def import_bake(folder, startup_scene=False, moved_cube=False, **options):
    """Imports `folder` into an empty scene, or into Blender's startup scene (cube, light,
    camera), its cube moved aside when `moved_cube`."""
    bpy.ops.wm.read_factory_settings(use_empty=not startup_scene)
    if moved_cube:
        bpy.data.objects["Cube"].location.x = 3.0
    if addon_utils.enable("airtrap_importer", default_set=True) is None:
        fail("the add-on does not enable")
    if bpy.ops.import_scene.airtrap_bake(directory=folder, **options) != {'FINISHED'}:
        fail("the import of %s with %s did not finish" % (folder, options))


def object_named(name):
    obj = bpy.data.objects.get(name)
    if obj is None:
        fail("no %s object (the scene has %s)" % (name, sorted(bpy.data.objects.keys())))
    return obj


def check_mesh_sequence(obj, folder, stem, frames):
    for frame in frames:
        expected = obj_counts(os.path.join(folder, "%s_%04d.obj" % (stem, frame)))
        mesh = evaluated_mesh(obj, frame)
        got = (len(mesh.vertices), len(mesh.polygons))
        if got != expected:
            fail("frame %d: %s has %s vertices and faces, %s_%04d.obj %s"
                 % (frame, obj.name, got, stem, frame, expected))
        print("frame %d: %s has %d vertices, %d faces, as in the OBJ"
              % ((frame, obj.name) + got))


def sphere_blocks(mesh):
    """Per realised sphere: its centre, radius and the velocity on its vertices."""
    count = len(mesh.vertices)
    positions = array('f', [0.0]) * (3 * count)
    mesh.vertices.foreach_get("co", positions)
    velocities = array('f', [0.0]) * (3 * count)
    mesh.attributes["velocity"].data.foreach_get("vector", velocities)
    blocks = []
    for first in range(0, count, SPHERE_VERTICES):
        points = [positions[3 * v:3 * v + 3] for v in range(first, first + SPHERE_VERTICES)]
        centre = [sum(p[axis] for p in points) / len(points) for axis in range(3)]
        radius = math.dist(points[0], centre)
        blocks.append((centre, radius, tuple(velocities[3 * first:3 * first + 3])))
    return blocks


def mesh_box(obj, frame):
    mesh = evaluated_mesh(obj, frame)
    corners = [v.co for v in mesh.vertices]
    return [min(c[axis] for c in corners) for axis in range(3)] + \
        [max(c[axis] for c in corners) for axis in range(3)]


def world_box(obj, frame):
    """The world-space box of an object's evaluated bounds (a volume's grids)."""
    bpy.context.scene.frame_set(frame)
    evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
    corners = [evaluated.matrix_world @ Vector(c) for c in evaluated.bound_box]
    return [min(c[axis] for c in corners) for axis in range(3)] + \
        [max(c[axis] for c in corners) for axis in range(3)]


def same_place(name, got, expected, tolerance):
    if len(got) != len(expected) or any(abs(a - b) > tolerance for a, b in zip(got, expected)):
        fail("Y up: %s is at %s, Z up at %s" % (name, [round(v, 5) for v in got],
                                                 [round(v, 5) for v in expected]))


def check_spheres(bubbles, frame):
    columns = ply_points.read_points(os.path.join(export_dir, "bubbles_%04d.ply" % frame))
    mesh = evaluated_mesh(bubbles, frame)
    points = len(columns.get("pscale", []))
    if frame == last and points == 0:
        fail("bubbles_%04d.ply has no bubbles: the check would prove nothing" % frame)
    if len(mesh.vertices) != SPHERE_VERTICES * points:
        fail("frame %d: Bubbles has %d vertices, not %d spheres of %d"
             % (frame, len(mesh.vertices), points, SPHERE_VERTICES))
    if points == 0:
        return
    for i, (centre, radius, velocity) in enumerate(sphere_blocks(mesh)):
        at = (columns["x"][i], columns["y"][i], columns["z"][i])
        moving = (columns["vx"][i], columns["vy"][i], columns["vz"][i])
        pscale = columns["pscale"][i]
        if math.dist(centre, at) > 1e-4 or abs(radius - pscale) > 1e-4 * max(pscale, 1e-3) \
                or math.dist(velocity, moving) > 1e-5 * max(1.0, math.hypot(*moving)):
            fail("frame %d, bubble %d: sphere at %s radius %g velocity %s; the PLY says %s, "
                 "pscale %g, velocity %s" % (frame, i, centre, radius, velocity, at, pscale,
                                             moving))
    print("frame %d: %d bubble spheres at the points, radius = pscale, velocity = (vx, vy, vz)"
          % (frame, points))


# The default import: spheres, no volume, a preview scene.
import_bake(export_dir)
scene = bpy.context.scene
first, last = scene.frame_start, scene.frame_end
if (first, last) != (1, 15):
    fail("the scene plays %d–%d, the export 1–15" % (first, last))
check_mesh_sequence(object_named("Water"), export_dir, "water", (first, last))
active = bpy.context.view_layer.objects.active
selected = [obj.name for obj in bpy.context.selected_objects]
if active is None or active.name != "Water" or selected != ["Water"]:
    fail("after the import the active object is %s and %s are selected, not Water"
         % (active and active.name, selected))
bubbles = object_named("Bubbles")
for frame in (first, last):
    check_spheres(bubbles, frame)
subgrid_points = len(ply_points.read_points(
    os.path.join(export_dir, "subgrid_%04d.ply" % last)).get("x", []))
subgrid_vertices = len(evaluated_mesh(object_named("Sub-grid bubbles"), last).vertices)
if subgrid_points == 0 or subgrid_vertices != SPHERE_VERTICES * subgrid_points:
    fail("frame %d: Sub-grid bubbles has %d vertices, subgrid_%04d.ply %d points"
         % (last, subgrid_vertices, last, subgrid_points))
print("frame %d: %d sub-grid bubble spheres, one per point" % (last, subgrid_points))
if scene.camera is None or scene.render.engine != 'CYCLES' or scene.world is None:
    fail("no preview scene: camera %s, engine %s, world %s"
         % (scene.camera, scene.render.engine, scene.world))
for name in ("Airtrap sun", "Airtrap floor", "Airtrap tank"):
    object_named(name)
print("preview scene: camera, sun, sky, floor, tank, Cycles")
z_up = {"water": mesh_box(object_named("Water"), last),
        "bubbles": sorted((c, v) for c, _, v in sphere_blocks(evaluated_mesh(bubbles, last))),
        "camera": list(scene.camera.location)}

saved = os.path.join(work_dir, "imported.blend")
bpy.ops.wm.save_as_mainfile(filepath=saved)
# A fresh Blender, factory settings, no add-on: the water still follows the frame.
check = ("import bpy; s = bpy.context.scene; w = bpy.data.objects['Water']; s.frame_set(%d); "
         "m = w.evaluated_get(bpy.context.evaluated_depsgraph_get()).data; "
         "print('FRESH', len(m.vertices), len(m.polygons))" % last)
fresh = subprocess.run([bpy.app.binary_path, "-b", "--factory-startup", saved,
                        "--python-expr", check], capture_output=True, text=True)
line = next((l for l in fresh.stdout.splitlines() if l.startswith("FRESH")), None)
expected = obj_counts(os.path.join(export_dir, "water_%04d.obj" % last))
if line is None or tuple(int(x) for x in line.split()[1:]) != expected:
    fail("in a fresh Blender the Water at frame %d is %s, expected %s"
         % (last, line, expected))
print("fresh Blender without the add-on: frame %d matches" % last)

# The other options: oscillating bubble meshes, the volume, no preview.
import_bake(export_dir, bubble_shape='MESHES', import_volume=True, preview_scene=False)
volume = object_named("Water volume")
if volume.visible_shadow:
    fail("the volume casts shadows, which the water's surface does not")
# Named by the import itself, before any frame change loads the grids.
if volume.data.velocity_grid != "vel":
    fail("the volume's velocity grid is %r after the import, not 'vel'"
         % volume.data.velocity_grid)
check_mesh_sequence(object_named("Bubbles"), export_dir, "bubbles", (first, last))
bpy.context.scene.frame_set(last)
volume.data.grids.load()
grids = sorted(grid.name for grid in volume.data.grids)
if "density" not in grids or volume.data.velocity_grid != "vel" or \
        volume.data.grids.frame_filepath != os.path.join(export_dir, "fluid_%04d.vdb" % last):
    fail("the volume at frame %d reads %s with grids %s, velocity grid %r"
         % (last, volume.data.grids.frame_filepath, grids, volume.data.velocity_grid))
print("volume at frame %d: %s, grids %s" % (last, os.path.basename(
    volume.data.grids.frame_filepath), ", ".join(grids)))
if bpy.context.scene.camera is not None or bpy.data.objects.get("Airtrap floor") is not None:
    fail("preview_scene=False made a preview scene")
z_up["volume"] = world_box(volume, last)

# The same bake exported Y up: turned to Blender's Z up, everything lands where it did.
import_bake(y_up_dir, import_volume=True)
same_place("the water", mesh_box(object_named("Water"), last), z_up["water"], 1e-5)
spheres = sorted((c, v) for c, _, v in
                 sphere_blocks(evaluated_mesh(object_named("Bubbles"), last)))
same_place("the bubbles and their velocities", [x for c, v in spheres for x in c + list(v)],
           [x for c, v in z_up["bubbles"] for x in c + list(v)], 1e-5)
same_place("the volume", world_box(object_named("Water volume"), last), z_up["volume"], 1e-4)
same_place("the camera", list(bpy.context.scene.camera.location), z_up["camera"], 1e-4)
print("Y-up export: water, bubbles, velocities, volume and camera where the Z-up export puts "
      "them")

# Imported again into the same scene: one camera and one sun, the new import's.
if bpy.ops.import_scene.airtrap_bake(directory=y_up_dir) != {'FINISHED'}:
    fail("the second import did not finish")
for prefix in ("Airtrap camera", "Airtrap sun", "Airtrap floor", "Airtrap tank"):
    found = [o.name for o in bpy.data.objects if o.name.startswith(prefix)]
    if len(found) != 1:
        fail("after a second import the scene has %s" % found)
print("a second import replaces the first one's preview")

# Into Blender's startup scene, as an artist does: its untouched cube (2 m at the origin, over
# the tank), light and camera go, so that the preview camera sees the water; a cube that was
# moved shows a scene worked in, and everything in it stays.
import_bake(export_dir, startup_scene=True)
left = sorted(name for name in ("Cube", "Light", "Camera") if name in bpy.data.objects)
if left or bpy.context.scene.camera.name != "Airtrap camera" or "Cube" in bpy.data.meshes:
    fail("imported into the startup scene, %s stayed and the camera is %s"
         % (left, bpy.context.scene.camera.name))
import_bake(export_dir, startup_scene=True, moved_cube=True)
left = sorted(name for name in ("Cube", "Light", "Camera") if name in bpy.data.objects)
if left != ["Camera", "Cube", "Light"]:
    fail("imported into a startup scene whose cube was moved, only %s stayed" % left)
print("startup scene: the untouched cube, light and camera removed; a moved cube kept")

# Bodies, from three frames of the buoyancy sample.
import_bake(bodies_dir)
check_mesh_sequence(object_named("Bodies"), bodies_dir, "bodies", (1, 3))
print("PASS")
