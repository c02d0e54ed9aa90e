# Whether a sequence file may be handed to a reader: Blender's OpenVDB aborts the whole program on
# a damaged volume file (a cut-off one included), so every file is checked before it is read.
# Against the CRC-32 export.json lists for it when there is one (docs/CLI.md "export"); a volume
# without one must at least start as an OpenVDB file does. Pure Python, so that it reads the same
# outside Blender.
import os
import zlib

# OpenVDB's magic number, 0x56444220 ("VDB "), as the little-endian 64-bit integer every .vdb
# file starts with.
VDB_MAGIC = b" BDV\0\0\0\0"
CHUNK_BYTES = 1 << 20


def crc32_of(path):
    """zlib's CRC-32 of the file's bytes."""
    crc = 0
    with open(path, "rb") as file:
        for chunk in iter(lambda: file.read(CHUNK_BYTES), b""):
            crc = zlib.crc32(chunk, crc)
    return crc & 0xFFFFFFFF


def damage(path, listed_crc32, ext):
    """Why `path` must not be read, or None when it may: its bytes are not those export.json
    lists (`listed_crc32`, None when it lists none), or a volume does not start as one."""
    try:
        if listed_crc32 is not None:
            if crc32_of(path) != listed_crc32:
                return ("is damaged or cut short (its CRC-32 is not the one export.json lists; "
                        "export it again)")
            return None
        if ext == "vdb":
            with open(path, "rb") as file:
                if file.read(len(VDB_MAGIC)) != VDB_MAGIC:
                    return "is not an OpenVDB file (empty or damaged; export vdb again)"
    except OSError as error:
        return "cannot be read (%s)" % (error.strerror or error)
    return None


def summarised(paths, one, many, most=3):
    """One warning per path ("PATH `one`"), or, past `most`, one for them all ("N files of
    FOLDER, FIRST to LAST, `many`")."""
    if len(paths) <= most:
        return ["%s %s" % (path, one) for path in paths]
    return ["%d files of %s, %s to %s, %s" % (len(paths), os.path.dirname(paths[0]),
                                              os.path.basename(paths[0]),
                                              os.path.basename(paths[-1]), many)]
