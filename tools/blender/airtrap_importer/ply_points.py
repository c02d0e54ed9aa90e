# The point files Airtrap exports (bubbles_####.ply, subgrid_####.ply: binary little-endian PLY
# with one `vertex` element; docs/CLI.md "export"), read without numpy, which Debian's Blender
# does not bundle. Blender's own PLY importer drops the `pscale` and `vx vy vz` properties.
import struct

TYPES = {"float": "f", "float32": "f", "double": "d", "float64": "d", "uint": "I",
         "uint32": "I", "int": "i", "int32": "i", "uchar": "B", "uint8": "B", "char": "b",
         "int8": "b", "ushort": "H", "uint16": "H", "short": "h", "int16": "h"}


POSITION = ("x", "y", "z")


class PlyError(Exception):
    """A file that is not a PLY point file of the kind Airtrap writes, naming what is wrong."""


def read_points(path):
    """{property name: list of values} for the vertices of `path`."""
    with open(path, "rb") as file:
        data = file.read()
    end = data.find(b"end_header\n")
    if not data.startswith(b"ply\n"):
        raise PlyError("%s is not a PLY file (no ply header)" % path)
    if end < 0:
        raise PlyError("%s is cut short in its header (no end_header line)" % path)
    header = data[:end].decode("ascii", "replace").splitlines()
    if "format binary_little_endian 1.0" not in header:
        raise PlyError("%s is not binary little-endian PLY 1.0" % path)
    count, names, codes, in_vertex = None, [], "", False
    for line in header:
        words = line.split()
        if words[:2] == ["element", "vertex"] and len(words) == 3:
            if not words[2].isdigit():
                raise PlyError("%s: %r does not give a point count" % (path, line))
            count, in_vertex = int(words[2]), True
        elif words[:1] == ["element"]:
            in_vertex = False
        elif words[:1] == ["property"] and in_vertex:
            if len(words) != 3 or words[1] not in TYPES:
                raise PlyError("%s: property line %r is not a scalar property" % (path, line))
            codes += TYPES[words[1]]
            names.append(words[2])
    if count is None:
        raise PlyError("%s has no vertex element" % path)
    missing = [axis for axis in POSITION if axis not in names]
    if missing:
        raise PlyError("%s has no %s property: its points have no position"
                       % (path, " ".join(missing)))
    record = struct.Struct("<" + codes)
    body = data[end + len(b"end_header\n"):]
    if len(body) < count * record.size:
        raise PlyError("%s is cut short: %d of %d bytes of its %d points"
                       % (path, len(body), count * record.size, count))
    columns = {name: [] for name in names}
    for values in record.iter_unpack(body[:count * record.size]):
        for name, value in zip(names, values):
            columns[name].append(value)
    return columns
