# Every OBJ Airtrap exports ends with the line "# end: V vertices, T triangles" (docs/CLI.md
# "export"). Blender's OBJ importer reads a cut-off file without a word, so the add-on reads this
# line first: a file without it is not whole. Pure Python, so that it reads the same outside
# Blender.
import os
import re

TRAILER = re.compile(rb"# end: (\d+) vertices, (\d+) triangles\r?\n?$")
TAIL_BYTES = 128


class ObjCutShort(Exception):
    """An OBJ without its closing line, with a message naming the file."""


def triangle_count(path):
    """The number of triangles the closing line of `path` promises; ObjCutShort without it."""
    with open(path, "rb") as file:
        file.seek(max(0, os.path.getsize(path) - TAIL_BYTES))
        tail = file.read()
    match = TRAILER.search(tail)
    if match is None:
        raise ObjCutShort("%s is cut short (it lacks the closing line `# end: V vertices, T "
                          "triangles` every Airtrap OBJ has)" % path)
    return int(match.group(2))
