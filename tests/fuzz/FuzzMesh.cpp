// libFuzzer target: the mesh loader (MeshLoader::load) on OBJ text, the path a body's mesh file
// takes: our own checks, ObjText's repair, then assimp. The input is written to a file, as the
// loader reads files.
#include "core/Error.h"
#include "rigid/MeshLoader.h"

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string path = "fuzz_mesh_" + std::to_string(::getpid()) + ".obj";
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), std::streamsize(size));
    try {
        (void)airtrap::MeshLoader::load(path);
    } catch (const airtrap::Error& error) {
        if (error.kind() != airtrap::ErrorKind::InvalidInput)
            __builtin_trap();
    }
    return 0;
}
