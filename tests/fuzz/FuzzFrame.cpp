// libFuzzer target: the cache frame reader (decodeFrame) and the checks every frame read gets.
// Anything but a decoded frame or Error(CacheCorrupt) is a finding.
#include "FuzzInput.h"
#include "cache/FrameValueCheck.h"
#include "core/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::uint8_t> bytes = airtrap::fuzz::bytesOf(data, size);
    airtrap::fuzz::fixFrameChecksums(bytes);
    try {
        const airtrap::FrameData frame = airtrap::decodeFrame(bytes, "fuzz.atf");
        airtrap::checkFrameLiesInDomain(frame, {airtrap::Vec3d::Zero(), airtrap::Vec3d::Ones()},
                                        1.0, "fuzz.atf");
    } catch (const airtrap::Error& error) {
        if (error.kind() != airtrap::ErrorKind::CacheCorrupt)
            __builtin_trap();
    }
    return 0;
}
