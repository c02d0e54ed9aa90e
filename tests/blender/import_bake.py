# Run by ctest (label blender) as
#   blender -b --factory-startup --python import_bake.py -- EXPORT_DIR WORK_DIR
# The add-on enables; the import makes a Water object whose mesh at the first and last frames has
# exactly the vertices and faces of water_000N.obj, and Bubbles whose sphere instances are the
# points of bubbles_000N.ply with their pscale as radius; saved, the file plays the water in a
# fresh Blender without the add-on. Exits non-zero on the first failure, naming it.
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "blender"))

import addon_utils  # noqa: E402 (the add-on's folder goes on the path first)
import bpy  # noqa: E402

from airtrap_importer import ply_points  # noqa: E402


export_dir, work_dir = (os.path.abspath(a) for a in sys.argv[sys.argv.index("--") + 1:][:2])


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


def evaluated_counts(obj, frame):
    bpy.context.scene.frame_set(frame)
    mesh = obj.evaluated_get(bpy.context.evaluated_depsgraph_get()).data
    return len(mesh.vertices), len(mesh.polygons)


bpy.ops.wm.read_factory_settings(use_empty=True)
if addon_utils.enable("airtrap_importer", default_set=True) is None:
    fail("the add-on does not enable")
if bpy.ops.import_scene.airtrap_bake(directory=export_dir) != {'FINISHED'}:
    fail("the import did not finish")
water = bpy.data.objects.get("Water")
if water is None:
    fail("no Water object")
scene = bpy.context.scene
first, last = scene.frame_start, scene.frame_end
for frame in (first, last):
    expected = obj_counts(os.path.join(export_dir, "water_%04d.obj" % frame))
    got = evaluated_counts(water, frame)
    if got != expected:
        fail("frame %d: Water has %s vertices and faces, water_%04d.obj %s"
             % (frame, got, frame, expected))
    print("frame %d: %d vertices, %d faces, as in the OBJ" % ((frame,) + got))

bubbles = bpy.data.objects.get("Bubbles")
if bubbles is None:
    fail("no Bubbles object")
for frame in (first, last):
    radii = sorted(ply_points.read_points(
        os.path.join(export_dir, "bubbles_%04d.ply" % frame)).get("pscale", []))
    scene.frame_set(frame)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    scales = sorted(instance.matrix_world.to_scale()[0]
                    for instance in depsgraph.object_instances
                    if instance.is_instance and instance.parent is not None
                    and instance.parent.original == bubbles)
    if frame == last and not radii:
        fail("bubbles_%04d.ply has no bubbles: the check would prove nothing" % frame)
    if len(scales) != len(radii) or any(abs(a - b) > 1e-6 * max(1.0, b)
                                        for a, b in zip(scales, radii)):
        fail("frame %d: %d bubble spheres with radii %s, bubbles_%04d.ply has %d with %s"
             % (frame, len(scales), scales[:5], frame, len(radii), radii[:5]))
    print("frame %d: %d bubble spheres, radii = pscale" % (frame, len(scales)))

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
print("PASS")
