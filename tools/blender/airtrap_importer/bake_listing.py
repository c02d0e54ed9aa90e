# What an Airtrap export folder holds, from its export.json (docs/CLI.md "export"): the scene's
# name, fps and frame range, and per sequence its files, frames and up axis. Pure Python, so that
# it reads the same inside and outside Blender.
import json
import os

FORMAT_NAME = "airtrap-export"
VERSION = 1


class ListingError(Exception):
    """A folder that cannot be imported, with a message for the user."""


def sequence_file_name(stem, frame, ext):
    """The file of `frame` in a sequence: water_0001.obj; more digits from frame 10000 on."""
    return "%s_%04d.%s" % (stem, frame, ext)


class Sequence:
    def __init__(self, key, entry, directory):
        stem, _, ext = key.rpartition(".")
        self.key = key
        self.stem = stem
        self.ext = ext
        self.up_axis = entry.get("up_axis", "y")
        self.frames = sorted(int(f) for f in entry.get("frames", []))
        self.directory = directory

    def path(self, frame):
        return os.path.join(self.directory, sequence_file_name(self.stem, frame, self.ext))

    def present_frames(self):
        """The listed frames whose file exists, and the paths of those that are missing."""
        present, missing = [], []
        for frame in self.frames:
            (present if os.path.isfile(self.path(frame)) else missing).append(frame)
        return present, [self.path(frame) for frame in missing]


class BakeListing:
    def __init__(self, directory, json_data):
        self.directory = directory
        self.scene_name = str(json_data.get("scene", os.path.basename(directory.rstrip("/"))))
        self.fps = float(json_data.get("fps", 30.0))
        self.frame_start = int(json_data.get("frame_start", 1))
        self.frame_end = int(json_data.get("frame_end", self.frame_start))
        self.sequences = {
            key: Sequence(key, entry, directory)
            for key, entry in json_data.get("sequences", {}).items()
            if isinstance(entry, dict)
        }

    def sequence(self, key):
        return self.sequences.get(key)


def read_listing(directory):
    """The listing of an export folder, or ListingError saying what the folder is instead."""
    directory = os.path.abspath(directory)
    if not os.path.isdir(directory):
        raise ListingError("%s is not a folder" % directory)
    path = os.path.join(directory, "export.json")
    if not os.path.isfile(path):
        if os.path.isfile(os.path.join(directory, "manifest.json")):
            raise ListingError(
                "%s is an Airtrap cache, not an export: run `airtrap-cli post %s` and "
                "`airtrap-cli export %s --format obj --out FOLDER --up z` (and --format ply, "
                "vdb), then import FOLDER" % (directory, directory, directory))
        raise ListingError(
            "%s has no export.json: it is not an Airtrap export (made by `airtrap-cli export`)"
            % directory)
    try:
        with open(path, "r", encoding="utf-8") as file:
            data = json.load(file)
    except (OSError, ValueError) as error:
        raise ListingError("%s cannot be read: %s" % (path, error))
    if not isinstance(data, dict) or data.get("format") != FORMAT_NAME:
        raise ListingError("%s is not an Airtrap export listing (format is not %r)"
                           % (path, FORMAT_NAME))
    if data.get("version") != VERSION:
        raise ListingError("%s has version %r; this add-on reads version %d"
                           % (path, data.get("version"), VERSION))
    listing = BakeListing(directory, data)
    if not listing.sequences:
        raise ListingError("%s lists no sequences: export with `airtrap-cli export %s ...`"
                           % (path, directory))
    return listing
