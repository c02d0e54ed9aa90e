# fluid_####.vdb as a volume sequence Blender plays and renders by itself: its `density` grid
# (0 outside the water, 1 inside) shaded as a light fog, its `vel` grid for Cycles' motion blur.
import math

import bpy

from . import materials


def import_volume_sequence(sequence, name, collection, report):
    """`sequence` (fluid_####.vdb) as the volume object `name` in `collection`, or None when its
    first file is damaged."""
    present, damaged, warnings = sequence.usable_frames()
    for warning in warnings:
        report.warn(warning)
    first, last = sequence.frames[0], sequence.frames[-1]
    if damaged:
        # Blender reads a sequence's files by itself and aborts on a damaged one: the volume
        # stops before it. A missing file only shows nothing.
        if damaged[0] == first:
            report.warn("%s is damaged: the volume is not imported" % sequence.path(first))
            return None
        last = damaged[0] - 1
        report.warn("%s is damaged: the volume stops at frame %d (Blender cannot read it)"
                    % (sequence.path(damaged[0]), last))
        present = [frame for frame in present if frame <= last]
    volume = bpy.data.volumes.new(name)
    volume.filepath = sequence.path(present[0] if present else first)
    # The grids load for the current frame; as a single file first, so that they do now and the
    # velocity grid can be named (Blender checks the name against the loaded grids).
    volume.grids.load()
    if any(grid.name == "vel" for grid in volume.grids):
        volume.velocity_grid = "vel"
        volume.velocity_unit = 'SECOND'
    volume.is_sequence = True
    # Blender numbers a sequence's files from the file at frame_start as 1, plus frame_offset:
    # with the offset first - 1 the file of frame f is fluid_f.vdb, as exported.
    volume.frame_start = first
    volume.frame_offset = first - 1
    volume.frame_duration = last - first + 1
    volume.sequence_mode = 'CLIP'
    volume.materials.append(materials.volume_material())
    obj = bpy.data.objects.new(name, volume)
    # The water's surface lets shadow rays through (materials.water_material); the fog inside
    # would otherwise cast a dark smudge on the floor beside the tank.
    obj.visible_shadow = False
    if sequence.up_axis != "z":
        # A Y-up export's grids, turned as the OBJ importer turns its meshes: y up becomes z up.
        obj.rotation_euler = (math.pi / 2, 0.0, 0.0)
    collection.objects.link(obj)
    return obj
