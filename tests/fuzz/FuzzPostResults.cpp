// libFuzzer target: the post stage's result readers, the free-surface mesh file (MeshFile) and
// the sub-grid bubble file (SubgridFile). The first input byte picks the reader; the rest is the
// file, its trailing CRC-32 recomputed.
#include "FuzzInput.h"
#include "core/Error.h"
#include "post/MeshFile.h"
#include "post/SubgridFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0)
        return 0;
    std::vector<std::uint8_t> bytes = airtrap::fuzz::bytesOf(data + 1, size - 1);
    airtrap::fuzz::fixTrailingChecksum(bytes);
    try {
        if (data[0] % 2 == 0)
            airtrap::MeshFile::decode(bytes, "fuzz.atm");
        else
            airtrap::SubgridFile::decode(bytes, "fuzz.atb");
    } catch (const airtrap::Error& error) {
        if (error.kind() != airtrap::ErrorKind::CacheCorrupt)
            __builtin_trap();
    }
    return 0;
}
