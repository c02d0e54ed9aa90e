#pragma once
// Crash-safe file replacement: a reader sees either the old file or the complete new one, never a
// half-written one. The cache relies on this for frames and the manifest (docs/CACHE_FORMAT.md
// "Writing: the atomic protocol").
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace airtrap {

class AtomicFile {
public:
    //! Writes `size` bytes to a unique temporary file next to `path`, fsyncs it, renames it over
    //! `path` and fsyncs the folder. On failure the temporary is removed, `path` is left as it
    //! was, and Error(Io) names `path` and the OS reason ("disk full", "permission denied").
    static void write(const std::string& path, const void* data, std::size_t size);
    static void write(const std::string& path, const std::vector<std::uint8_t>& bytes);
    static void write(const std::string& path, const std::string& text);

    //! Reads a whole file. Throws Error(Io) naming `path` and the OS reason.
    static std::vector<std::uint8_t> read(const std::string& path);

    //! "<action> <path>: <reason>", with errno translated into words a user acts on.
    static std::string errorMessage(const std::string& action, const std::string& path, int err);

    //! True when `name` is one of the temporaries write() creates (they end in ".tmp").
    static bool isTemporaryName(const std::string& name);

    //! Deletes the temporaries write() left in `dir` (not its subfolders) when their process died
    //! before the rename (kill -9, a crash, power loss): those named after a process that no
    //! longer runs. A writer still running keeps its own. Best effort: a file that cannot be
    //! deleted stays, harmless. Returns how many were deleted.
    static std::size_t removeOrphanedTemporaries(const std::string& dir);
};

} // namespace airtrap
