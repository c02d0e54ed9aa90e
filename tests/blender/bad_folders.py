# Run by ctest (label blender) as
#   blender -b --factory-startup --python-exit-code 1 --python bad_folders.py -- EXPORT_DIR CACHE_DIR WORK_DIR
# Folders the import cannot take say why, with no traceback; a missing frame, a damaged or
# cut-off OBJ, PLY or VDB, a missing export.json and a frame range that does not match are named
# in a warning while the rest imports. Exits non-zero on the first failure, naming it.
import contextlib
import io
import json
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


def import_folder(folder, **options):
    """The operator's result; what it printed (its warnings) is kept in `messages` and shown."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    addon_utils.enable("airtrap_importer", default_set=True)
    console = io.StringIO()
    try:
        with contextlib.redirect_stdout(console):
            return bpy.ops.import_scene.airtrap_bake(directory=folder, preview_scene=False,
                                                     **options)
    except RuntimeError as error:  # the operator's ERROR report is raised in background mode
        messages.append(str(error))
        return {'CANCELLED'}
    finally:
        messages.extend(console.getvalue().splitlines())
        print(console.getvalue(), end="")


def copy_of_export(name):
    folder = os.path.join(work_dir, name)
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(export_dir, folder)
    return folder


def imports_warning(folder, fragments, **options):
    messages.clear()
    if import_folder(folder, **options) != {'FINISHED'}:
        fail("%s did not import: %s" % (folder, messages))
    for fragment in fragments:
        if not any(fragment in message for message in messages):
            fail("importing %s did not say %r: %s" % (folder, fragment, messages))


def water_vertices(frame):
    bpy.context.scene.frame_set(frame)
    water = bpy.data.objects.get("Water")
    return len(water.evaluated_get(bpy.context.evaluated_depsgraph_get()).data.vertices)


def cut_short(path, keep):
    with open(path, "rb") as file:
        data = file.read()
    with open(path, "wb") as file:
        file.write(data[:int(len(data) * keep)])


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
holed = copy_of_export("holed")
os.remove(os.path.join(holed, "water_0003.obj"))
imports_warning(holed, [os.path.join(holed, "water_0003.obj") + " is missing"])
if [water_vertices(f) == 0 for f in (2, 3, 4)] != [False, True, False]:
    fail("with water_0003.obj missing, frames 2, 3, 4 have %s water vertices"
         % [water_vertices(f) for f in (2, 3, 4)])
print("missing water_0003.obj skipped, frames 2 and 4 imported")

# Cut-off files: the OBJ's frame shows no water, the PLY's no bubbles; both are named.
truncated = copy_of_export("truncated")
cut_short(os.path.join(truncated, "water_0005.obj"), 0.66)
cut_short(os.path.join(truncated, "bubbles_0015.ply"), 0.9)
# export.json lists each file's CRC-32, which the cut files no longer match.
imports_warning(truncated, [os.path.join(truncated, "water_0005.obj") + " is damaged or cut short",
                            os.path.join(truncated, "bubbles_0015.ply") + " is damaged or cut "
                                                                          "short"])
if [water_vertices(f) == 0 for f in (4, 5, 6)] != [False, True, False]:
    fail("with water_0005.obj cut short, frames 4, 5, 6 have %s water vertices"
         % [water_vertices(f) for f in (4, 5, 6)])
print("cut-off water_0005.obj and bubbles_0015.ply named and skipped")
# Without export.json's checksums, an OBJ is known whole by its closing line and a PLY by its
# point count.
cut_unlisted = copy_of_export("cut-unlisted")
os.remove(os.path.join(cut_unlisted, "export.json"))
cut_short(os.path.join(cut_unlisted, "water_0005.obj"), 0.66)
cut_short(os.path.join(cut_unlisted, "bubbles_0015.ply"), 0.9)
imports_warning(cut_unlisted, [os.path.join(cut_unlisted, "water_0005.obj") + " is cut short",
                               os.path.join(cut_unlisted, "bubbles_0015.ply") + " is cut short"])
if water_vertices(5) != 0 or water_vertices(6) == 0:
    fail("unlisted, with water_0005.obj cut short, frames 5 and 6 have %d and %d water vertices"
         % (water_vertices(5), water_vertices(6)))
print("without export.json: cut-off OBJ and PLY named by their own checks and skipped")

# Damaged volumes: Blender's OpenVDB aborts the program on one, so the import never lets it
# read one. A damaged later frame: the volume stops before it; the first frame: no volume.
damaged_late = copy_of_export("vdb-late")
cut_short(os.path.join(damaged_late, "fluid_0010.vdb"), 0.5)
imports_warning(damaged_late, [os.path.join(damaged_late, "fluid_0010.vdb") + " is damaged: the "
                               "volume stops at frame 9"], import_volume=True)
volume = bpy.data.objects["Water volume"].data
if volume.frame_duration != 9:
    fail("the volume plays %d frames, not the 9 before the damaged fluid_0010.vdb"
         % volume.frame_duration)
for frame in (9, 10, 15):
    bpy.context.scene.frame_set(frame)
    volume.grids.load()  # aborts the test, and fails it, on a damaged file
print("a damaged fluid_0010.vdb: the volume stops at frame 9, frames 10 and 15 load nothing")
damaged_first = copy_of_export("vdb-first")
cut_short(os.path.join(damaged_first, "fluid_0001.vdb"), 0.3)
imports_warning(damaged_first, [os.path.join(damaged_first, "fluid_0001.vdb") + " is damaged: "
                                "the volume is not imported"], import_volume=True)
if "Water volume" in bpy.data.objects or "Water" not in bpy.data.objects:
    fail("with fluid_0001.vdb damaged: objects %s" % sorted(bpy.data.objects.keys()))
# No export.json: an empty volume file is told by its missing OpenVDB header.
empty_vdb = copy_of_export("vdb-empty")
os.remove(os.path.join(empty_vdb, "export.json"))
open(os.path.join(empty_vdb, "fluid_0001.vdb"), "wb").close()
imports_warning(empty_vdb, [os.path.join(empty_vdb, "fluid_0001.vdb") + " is not an OpenVDB "
                            "file"], import_volume=True)
print("a damaged or empty first volume file: no volume, the rest imported")

# Every listed bubble point file gone: one warning for them all, and the meshes instead.
points_gone = copy_of_export("points-gone")
for name in os.listdir(points_gone):
    if name.startswith("bubbles_") and name.endswith(".ply"):
        os.remove(os.path.join(points_gone, name))
imports_warning(points_gone, ["has no bubble points (bubbles_####.ply): the bubbles are the "
                              "meshes of bubbles_####.obj"])
if any("bubbles_0003.ply" in message for message in messages):
    fail("a warning per missing bubble file: %s" % messages)
print("bubble points all gone: one warning, the meshes imported instead")

# No export.json: the sequences are found by their file names, with a warning.
unlisted = copy_of_export("unlisted")
os.remove(os.path.join(unlisted, "export.json"))
imports_warning(unlisted, [unlisted + " has no export.json: frames 1–15 read from the file "
                                      "names, Z up"])
if (bpy.context.scene.frame_start, bpy.context.scene.frame_end) != (1, 15) \
        or water_vertices(15) == 0:
    fail("without export.json the scene plays %d–%d with %d water vertices at 15"
         % (bpy.context.scene.frame_start, bpy.context.scene.frame_end, water_vertices(15)))
print("no export.json: imported from the file names")

# A listing whose range does not match its sequences: said, and the scene plays them all.
mismatched = copy_of_export("mismatched")
listing_path = os.path.join(mismatched, "export.json")
with open(listing_path) as file:
    listing = json.load(file)
listing["frame_end"] = 12
listing["sequences"]["bubbles.ply"]["frames"] = list(range(1, 11))
with open(listing_path, "w") as file:
    json.dump(listing, file)
imports_warning(mismatched, ["gives the range 1–12, but ", "water.obj list frames 1–15: the "
                                                             "scene plays 1–15",
                             "bubbles.ply has frames 1–10 of 1–15: it shows nothing on the "
                             "others"])
if bpy.context.scene.frame_end != 15 or water_vertices(15) == 0:
    fail("the mismatched listing plays to %d" % bpy.context.scene.frame_end)
# bubbles_0015.ply has bubbles (BlenderImport checks), but the listing stops the sequence at 10.
bubbles = bpy.data.objects.get("Bubbles")
if len(bubbles.evaluated_get(bpy.context.evaluated_depsgraph_get()).data.vertices) != 0:
    fail("Bubbles shows something at frame 15, after its last listed frame")
print("mismatched frame range said, frames 1–15 imported")

def edit_listing(folder, change):
    path = os.path.join(folder, "export.json")
    with open(path) as file:
        listing = json.load(file)
    change(listing)
    with open(path, "w") as file:
        json.dump(listing, file)


# An OBJ whose triangles do not match its closing line: imported, and named.
# (Its listed checksum is taken out: with it, the changed file is skipped as damaged.)
miscounted = copy_of_export("miscounted")
with open(os.path.join(miscounted, "water_0002.obj"), "a") as file:
    file.write("# end: 1 vertices, 1 triangles\n")
edit_listing(miscounted, lambda listing: listing["sequences"]["water.obj"].pop("crc32"))
imports_warning(miscounted, ["water_0002.obj holds ", "triangles where its last line says 1"])
if water_vertices(2) == 0:
    fail("the miscounted water_0002.obj was not imported")
print("a miscounted OBJ imported and named")

# Only the oscillating meshes exported: the spheres asked for become those meshes, with a word.
meshes_only = copy_of_export("meshes-only")
edit_listing(meshes_only, lambda listing: listing["sequences"].pop("bubbles.ply"))
imports_warning(meshes_only, ["has no bubble points (bubbles_####.ply): the bubbles are the "
                              "meshes of bubbles_####.obj"])
print("bubble points missing: the meshes imported instead")

# A bake listed from frame 5: nothing before it, frame 5's files at frame 5 (volume included).
late = copy_of_export("late")


def from_frame_5(listing):
    listing["frame_start"] = 5
    for entry in listing["sequences"].values():
        entry["frames"] = [f for f in entry["frames"] if f >= 5]


edit_listing(late, from_frame_5)
messages.clear()
bpy.ops.wm.read_factory_settings(use_empty=True)
addon_utils.enable("airtrap_importer", default_set=True)
if bpy.ops.import_scene.airtrap_bake(directory=late, import_volume=True,
                                     preview_scene=False) != {'FINISHED'}:
    fail("the listing from frame 5 did not import")
if bpy.context.scene.frame_start != 5 or water_vertices(4) != 0 or water_vertices(5) == 0:
    fail("listed from frame 5: the scene starts at %d, water at 4 and 5 has %d and %d vertices"
         % (bpy.context.scene.frame_start, water_vertices(4), water_vertices(5)))
volume = bpy.data.objects["Water volume"].data
for frame in (5, 9):
    bpy.context.scene.frame_set(frame)
    volume.grids.load()
    if volume.grids.frame_filepath != os.path.join(late, "fluid_%04d.vdb" % frame):
        fail("at frame %d the volume reads %s" % (frame, volume.grids.frame_filepath))
print("listed from frame 5: nothing at 4, frame 5's water and volume at 5")

# Another version of the listing is refused.
newer = copy_of_export("newer")
edit_listing(newer, lambda listing: listing.update(version=2))
refused_saying(newer, "has version 2; this add-on reads version 1")

# A listing with no sequences says so.
bare = os.path.join(work_dir, "bare")
os.makedirs(bare, exist_ok=True)
with open(os.path.join(bare, "export.json"), "w") as file:
    json.dump({"format": "airtrap-export", "version": 1, "sequences": {}}, file)
refused_saying(bare, "lists no sequences")
malformed = os.path.join(work_dir, "malformed")
os.makedirs(malformed, exist_ok=True)
with open(os.path.join(malformed, "export.json"), "w") as file:
    json.dump({"format": "airtrap-export", "version": 1,
               "sequences": {"water.obj": {"frames": ["one"]}}}, file)
refused_saying(malformed, "has a malformed entry: sequences.water.obj.frames holds 'one', not a "
                          "whole frame number")
with open(os.path.join(malformed, "export.json"), "w") as file:
    json.dump({"format": "airtrap-export", "version": 1,
               "sequences": {"water.obj": {"frames": [1, 4.7]}}}, file)
refused_saying(malformed, "sequences.water.obj.frames holds 4.7")
with open(os.path.join(malformed, "export.json"), "w") as file:
    json.dump({"format": "airtrap-export", "version": 1, "fps": "abc",
               "sequences": {"water.obj": {"frames": [1]}}}, file)
refused_saying(malformed, "fps is 'abc', not a positive number")
refused_saying(os.path.join(work_dir, "no-such-folder"), "no-such-folder does not exist")
print("PASS")
