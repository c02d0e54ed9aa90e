# What an Airtrap export folder holds, from its export.json (docs/CLI.md "export"): the scene's
# name, fps and frame range, and per sequence its files, frames and up axis. Pure Python, so that
# it reads the same inside and outside Blender.
import json
import math
import os
import re

from . import file_check

FORMAT_NAME = "airtrap-export"
VERSION = 1
DEFAULT_FPS = 30.0
# More frames than a sequence's span may cover: a listing claiming more is damaged, and the
# import would make one object per frame of it.
MAX_FRAME_SPAN = 100000

# A sequence file as `airtrap-cli export` names it: stem, frame number (four digits or more), ext.
SEQUENCE_FILE = re.compile(r"^(water|bubbles|subgrid|bodies|particles|fluid)_(\d{4,})\.(obj|ply|vdb)$")
# The header comment OBJ and PLY exports carry: "metres, Z up".
UP_AXIS_COMMENT = re.compile(r"metres, ([YZ]) up")


class ListingError(Exception):
    """A folder that cannot be imported, with a message for the user."""


def sequence_file_name(stem, frame, ext):
    """The file of `frame` in a sequence: water_0001.obj; more digits from frame 10000 on."""
    return "%s_%04d.%s" % (stem, frame, ext)


def _frame_numbers(key, values):
    """A listed sequence's frames: whole numbers, or ValueError naming the sequence."""
    if not isinstance(values, list):
        raise ValueError("sequences.%s.frames is not a list" % key)
    frames = []
    for value in values:
        if isinstance(value, bool) or not isinstance(value, int):
            raise ValueError("sequences.%s.frames holds %r, not a whole frame number"
                             % (key, value))
        frames.append(value)
    return sorted(frames)


def _checksums(values):
    """{frame: CRC-32} from a listed sequence's `crc32` ({"1": 12345, ...}); entries that are
    not a frame and a 32-bit number are left out (their files are then checked as unlisted)."""
    if not isinstance(values, dict):
        return {}
    checksums = {}
    for frame, crc in values.items():
        if isinstance(frame, str) and frame.isdigit() and isinstance(crc, int) \
                and not isinstance(crc, bool) and 0 <= crc <= 0xFFFFFFFF:
            checksums[int(frame)] = crc
    return checksums


class Sequence:
    def __init__(self, key, entry, directory):
        stem, _, ext = key.rpartition(".")
        self.key = key
        self.stem = stem
        self.ext = ext
        self.up_axis = entry.get("up_axis", "y")
        self.frames = _frame_numbers(key, entry.get("frames", []))
        self.crc32 = _checksums(entry.get("crc32"))
        self.directory = directory
        # usable_frames() reads every file: once per import, however many ask.
        self._usable = None

    def frame_span(self):
        return "%d–%d" % (self.frames[0], self.frames[-1]) if self.frames else "none"

    def path(self, frame):
        return os.path.join(self.directory, sequence_file_name(self.stem, frame, self.ext))

    def present_frames(self):
        """The frames from the first to the last whose file exists, and the paths of those that
        are missing (listed or in a gap of the listing)."""
        present, missing = [], []
        for frame in range(self.frames[0], self.frames[-1] + 1) if self.frames else ():
            (present if os.path.isfile(self.path(frame)) else missing).append(frame)
        return present, [self.path(frame) for frame in missing]

    def usable_frames(self):
        """The frames from the first to the last whose file is there and whole, the damaged
        frames, and the warnings naming the missing and damaged files (one for many)."""
        if self._usable is None:
            self._usable = self._check_files()
        return self._usable

    def _check_files(self):
        present, missing = self.present_frames()
        usable, damaged, warnings = [], [], []
        for frame in present:
            reason = file_check.damage(self.path(frame), self.crc32.get(frame), self.ext)
            if reason is None:
                usable.append(frame)
            else:
                damaged.append(frame)
                # A volume's consequence is the volume's to say (volume_sequence).
                warnings.append("%s %s%s" % (self.path(frame), reason, "" if self.ext == "vdb"
                                             else ": its frame is skipped"))
        warnings += file_check.summarised(missing, "is missing: its frame is skipped",
                                          "are missing: their frames are skipped")
        return usable, damaged, warnings


def _whole(data, key, default):
    value = data.get(key, default)
    if isinstance(value, bool) or not isinstance(value, int):
        raise ValueError("%s is %r, not a whole frame number" % (key, value))
    return value


def _container_box(entry):
    """The tank's box as ((x, y, z) low, (x, y, z) high) in Blender's axes (z up), or None."""
    try:
        low, high = [float(v) for v in entry["min"]], [float(v) for v in entry["max"]]
        up_axis = entry.get("up_axis", "y")
    except (KeyError, TypeError, ValueError):
        return None
    if len(low) != 3 or len(high) != 3:
        return None
    if up_axis != "z":
        # y up to z up as the OBJ importer turns meshes: (x, y, z) → (x, −z, y).
        low, high = (low[0], -high[2], low[1]), (high[0], -low[2], high[1])
    return tuple(low), tuple(high)


class BakeListing:
    def __init__(self, directory, json_data):
        self.directory = directory
        # What the import should tell the user about the listing itself.
        self.warnings = []
        self.scene_name = str(json_data.get("scene", os.path.basename(directory.rstrip("/"))))
        self.fps = json_data.get("fps", DEFAULT_FPS)
        if isinstance(self.fps, bool) or not isinstance(self.fps, (int, float)) \
                or not math.isfinite(self.fps) or self.fps <= 0.0:
            raise ValueError("fps is %r, not a positive number" % (self.fps,))
        self.fps = float(self.fps)
        self.frame_start = _whole(json_data, "frame_start", 1)
        self.frame_end = _whole(json_data, "frame_end", self.frame_start)
        self.container = _container_box(json_data.get("container"))
        sequences = json_data.get("sequences", {})
        if not isinstance(sequences, dict):
            raise ValueError("sequences is not an object keyed by sequence (\"water.obj\": ...)")
        self.sequences = {
            key: Sequence(key, entry, directory)
            for key, entry in sequences.items()
            if isinstance(entry, dict) and entry.get("frames")
        }
        for sequence in self.sequences.values():
            if sequence.frames[-1] - sequence.frames[0] >= MAX_FRAME_SPAN:
                raise ValueError("%s spans frames %s" % (sequence.key, sequence.frame_span()))

    def sequence(self, key):
        return self.sequences.get(key)

    def check_frame_ranges(self):
        """Warns of sequences whose frames leave the export's range (the scene then plays them
        all) or stop short of it (the object shows nothing on the frames it lacks)."""
        listed = {key: s for key, s in self.sequences.items() if s.frames}
        outside = sorted(key for key, s in listed.items()
                         if s.frames[0] < self.frame_start or s.frames[-1] > self.frame_end)
        if outside:
            first = min(listed[key].frames[0] for key in outside)
            last = max(listed[key].frames[-1] for key in outside)
            start, end = min(first, self.frame_start), max(last, self.frame_end)
            self.warnings.append(
                "%s gives the range %d–%d, but %s list frames %d–%d: the scene plays %d–%d"
                % (os.path.join(self.directory, "export.json"), self.frame_start, self.frame_end,
                   ", ".join(outside), first, last, start, end))
            self.frame_start, self.frame_end = start, end
        for key in sorted(listed):
            frames = listed[key].frames
            if frames[0] > self.frame_start or frames[-1] < self.frame_end:
                self.warnings.append(
                    "%s has frames %s of %d–%d: it shows nothing on the others"
                    % (key, listed[key].frame_span(), self.frame_start, self.frame_end))


def _up_axis_of(path):
    """The up axis a sequence file's header comment states, or None."""
    try:
        with open(path, "rb") as file:
            head = file.read(512).decode("ascii", "replace")
    except OSError:
        return None
    match = UP_AXIS_COMMENT.search(head)
    return match.group(1).lower() if match else None


def listing_from_file_names(directory):
    """The listing of a folder of sequence files without export.json (copied without it), or
    None when the folder holds none. The frames come from the file names, the up axes from the
    OBJ and PLY headers; the frame rate is not known."""
    frames = {}
    try:
        names = os.listdir(directory)
    except OSError as error:
        raise ListingError("%s cannot be read: %s" % (directory, error.strerror or error))
    for name in names:
        match = SEQUENCE_FILE.match(name)
        if match:
            frames.setdefault("%s.%s" % (match.group(1), match.group(3)), []).append(
                int(match.group(2)))
    if not frames:
        return None
    # Each OBJ and PLY sequence says its axis in its first file's header; a volume says it in
    # OpenVDB metadata Blender does not show, so it takes the others' (exported together).
    axes = {}
    for key in frames:
        stem, _, ext = key.rpartition(".")
        if ext != "vdb":
            axes[key] = _up_axis_of(os.path.join(directory,
                                                 sequence_file_name(stem, min(frames[key]), ext)))
    up_axis = next((axes[key] for key in sorted(axes) if axes[key]), None)
    everything = [frame for listed in frames.values() for frame in listed]
    try:
        listing = BakeListing(directory, {
            "fps": DEFAULT_FPS, "frame_start": min(everything), "frame_end": max(everything),
            "sequences": {key: {"frames": listed, "up_axis": axes.get(key) or up_axis or "y"}
                          for key, listed in frames.items()}})
    except ValueError as error:
        raise ListingError("%s has no export.json, and its file names make no sequence (%s)"
                           % (directory, error))
    listing.warnings.append(
        "%s has no export.json: frames %d–%d read from the file names, %s up from their headers, "
        "%g frames per second assumed (export again with `airtrap-cli export` to list them)"
        % (directory, listing.frame_start, listing.frame_end,
           up_axis.upper() if up_axis else "Y (assumed)", DEFAULT_FPS))
    return listing


def read_listing(directory):
    """The listing of an export folder, or ListingError saying what the folder is instead."""
    directory = os.path.abspath(directory)
    if not os.path.isdir(directory):
        raise ListingError("%s %s" % (directory, "is not a folder" if os.path.exists(directory)
                                      else "does not exist"))
    path = os.path.join(directory, "export.json")
    if not os.path.isfile(path):
        if os.path.isfile(os.path.join(directory, "manifest.json")):
            raise ListingError(
                "%s is an Airtrap cache, not an export: run `airtrap-cli export %s --format "
                "obj --out FOLDER --up z` (and --format ply, vdb; `airtrap-cli post %s` first "
                "if export asks for it), then import FOLDER" % (directory, directory, directory))
        listing = listing_from_file_names(directory)
        if listing is None:
            raise ListingError(
                "%s has no export.json and no sequence files (water_0001.obj, "
                "bubbles_0001.ply, fluid_0001.vdb, ...): it is not an Airtrap export (made by "
                "`airtrap-cli export`)" % directory)
        listing.check_frame_ranges()
        return listing
    try:
        with open(path, "r", encoding="utf-8") as file:
            data = json.load(file)
    except (OSError, ValueError) as error:
        raise ListingError("%s cannot be read (%s): export again with `airtrap-cli export`, "
                           "which writes it afresh, or delete it to import the files by their "
                           "names" % (path, error))
    if not isinstance(data, dict) or data.get("format") != FORMAT_NAME:
        raise ListingError("%s is not an Airtrap export listing (format is not %r)"
                           % (path, FORMAT_NAME))
    if data.get("version") != VERSION:
        raise ListingError("%s has version %r; this add-on reads version %d"
                           % (path, data.get("version"), VERSION))
    try:
        listing = BakeListing(directory, data)
    except (TypeError, ValueError, AttributeError, OverflowError) as error:
        raise ListingError("%s has a malformed entry: %s (`fps` must be a positive number, "
                           "`frame_*` whole numbers, `sequences` an object whose entries list "
                           "whole `frames` fewer than %d apart; export again to rewrite it)"
                           % (path, error, MAX_FRAME_SPAN))
    if not listing.sequences:
        raise ListingError("%s lists no sequences with frames: export with "
                           "`airtrap-cli export %s ...`" % (path, directory))
    listing.check_frame_ranges()
    return listing
