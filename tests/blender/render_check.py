# Run by ctest (label blender) as
#   blender -b --factory-startup --python-exit-code 1 --python render_check.py -- EXPORT_DIR WORK_DIR
# The default import (with its preview scene) into Blender's startup scene, as an artist makes
# it, saved twice, once with the water hidden from the render; each file rendered at the last
# frame by a fresh Blender without the add-on, Cycles at low samples and a small size. The water must change a visible share of the picture, and the
# picture must not be flat. Exits non-zero on the first failure, naming it.
import os
import subprocess
import sys
from array import array

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "blender"))

import addon_utils  # noqa: E402 (the add-on's folder goes on the path first)
import bpy  # noqa: E402

export_dir, work_dir = (os.path.abspath(a) for a in sys.argv[sys.argv.index("--") + 1:][:2])
WIDTH, HEIGHT, SAMPLES = 200, 112, 8
# A pixel differs when a channel moves by more than this (0..1 display values): five steps of
# 8 bits. The renders share their random sequences, so pixels the water does not reach match
# exactly.
CHANNEL_STEP = 0.02
MIN_WATER_SHARE = 0.05
MIN_SPREAD = 0.02


def fail(text):
    print("FAIL: " + text)
    sys.exit(1)


def render_in_fresh_blender(blend, frame):
    """The PNG a fresh Blender (factory settings, no add-on) renders of `blend` at `frame`."""
    stem = os.path.splitext(blend)[0] + "_"
    run = subprocess.run([bpy.app.binary_path, "-b", "--factory-startup", blend, "-o",
                          stem + "####", "-F", "PNG", "-f", str(frame)],
                         capture_output=True, text=True)
    path = "%s%04d.png" % (stem, frame)
    if run.returncode != 0 or not os.path.isfile(path):
        fail("rendering %s at frame %d gave no picture (exit %d): %s"
             % (blend, frame, run.returncode, run.stderr[-2000:] or run.stdout[-2000:]))
    return path


def pixels(path):
    image = bpy.data.images.load(path)
    values = array('f', [0.0]) * len(image.pixels)
    image.pixels.foreach_get(values)
    return values


os.makedirs(work_dir, exist_ok=True)
bpy.ops.wm.read_factory_settings()
addon_utils.enable("airtrap_importer", default_set=True)
if bpy.ops.import_scene.airtrap_bake(directory=export_dir) != {'FINISHED'}:
    fail("the import did not finish")
scene = bpy.context.scene
frame = scene.frame_end
scene.render.resolution_x, scene.render.resolution_y = WIDTH, HEIGHT
scene.cycles.samples = SAMPLES
with_water = os.path.join(work_dir, "with_water.blend")
bpy.ops.wm.save_as_mainfile(filepath=with_water)
bpy.data.objects["Water"].hide_render = True
without_water = os.path.join(work_dir, "without_water.blend")
bpy.ops.wm.save_as_mainfile(filepath=without_water)

seen = pixels(render_in_fresh_blender(with_water, frame))
hidden = pixels(render_in_fresh_blender(without_water, frame))
count = len(seen) // 4
changed = sum(1 for p in range(count)
              if max(abs(seen[4 * p + c] - hidden[4 * p + c]) for c in range(3)) > CHANNEL_STEP)
light = [sum(seen[4 * p:4 * p + 3]) / 3.0 for p in range(count)]
mean = sum(light) / count
spread = (sum((v - mean) ** 2 for v in light) / count) ** 0.5
print("frame %d, %dx%d at %d samples: the water changes %.1f %% of the pixels; brightness "
      "%.3f ± %.3f" % (frame, WIDTH, HEIGHT, SAMPLES, 100.0 * changed / count, mean, spread))
if changed < MIN_WATER_SHARE * count:
    fail("the water changes %d of %d pixels, under %.0f %%"
         % (changed, count, 100 * MIN_WATER_SHARE))
if spread < MIN_SPREAD:
    fail("the picture is flat: brightness %.3f ± %.3f" % (mean, spread))
print("PASS")
