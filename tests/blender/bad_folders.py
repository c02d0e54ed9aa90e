# Run by ctest (label blender) as
#   blender -b --factory-startup --python-exit-code 1 --python bad_folders.py -- EXPORT_DIR CACHE_DIR WORK_DIR
# Folders the import cannot take say why, with no traceback; a missing frame is named and skipped
# while the rest imports. Exits non-zero on the first failure, naming it.
import os
import shutil
import sys

import addon_utils
import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "blender"))

export_dir, cache_dir, work_dir = sys.argv[sys.argv.index("--") + 1:][:3]
messages = []


def fail(text):
    print("FAIL: " + text)
    sys.exit(1)


def import_folder(folder):
    """The operator's result; its printed messages land in the console, which ctest keeps."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    addon_utils.enable("airtrap_importer", default_set=True)
    try:
        return bpy.ops.import_scene.airtrap_bake(directory=folder)
    except RuntimeError as error:  # the operator's ERROR report is raised in background mode
        messages.append(str(error))
        return {'CANCELLED'}


def refused_saying(folder, fragment):
    messages.clear()
    result = import_folder(folder)
    if result != {'CANCELLED'}:
        fail("%s was imported (%s)" % (folder, result))
    if not any(fragment in message for message in messages):
        fail("importing %s did not say %r: %s" % (folder, fragment, messages))
    print("refused %s: %s" % (os.path.basename(folder), messages[-1].strip()))


empty = os.path.join(work_dir, "empty")
os.makedirs(empty, exist_ok=True)
refused_saying(empty, "has no export.json")
refused_saying(cache_dir, "is an Airtrap cache, not an export")
foreign = os.path.join(work_dir, "foreign")
os.makedirs(foreign, exist_ok=True)
with open(os.path.join(foreign, "export.json"), "w") as file:
    file.write('{"format": "something else"}')
refused_saying(foreign, "is not an Airtrap export listing")
cut = os.path.join(work_dir, "cut")
os.makedirs(cut, exist_ok=True)
with open(os.path.join(cut, "export.json"), "w") as file:
    file.write('{"format": "airtrap-export", "vers')
refused_saying(cut, "cannot be read")

# A frame whose file is gone: named, skipped (it shows no water), the others import.
holed = os.path.join(work_dir, "holed")
shutil.rmtree(holed, ignore_errors=True)
shutil.copytree(export_dir, holed)
os.remove(os.path.join(holed, "water_0003.obj"))
if import_folder(holed) != {'FINISHED'}:
    fail("a folder with one missing frame did not import")
water = bpy.data.objects.get("Water")
scene = bpy.context.scene
for frame, empty_expected in ((2, False), (3, True), (4, False)):
    scene.frame_set(frame)
    mesh = water.evaluated_get(bpy.context.evaluated_depsgraph_get()).data
    if (len(mesh.vertices) == 0) != empty_expected:
        fail("frame %d has %d water vertices" % (frame, len(mesh.vertices)))
print("missing water_0003.obj skipped, frames 2 and 4 imported")
print("PASS")
