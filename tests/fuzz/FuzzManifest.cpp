// libFuzzer target: the cache manifest (CacheManifest::fromJson, after the JSON parse that
// CacheManifest::read does). Malformed JSON and any refused field are expected outcomes.
#include "cache/CacheManifest.h"
#include "core/Error.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const nlohmann::json json = nlohmann::json::parse(data, data + size, nullptr, false);
    if (json.is_discarded())
        return 0;
    try {
        const airtrap::CacheManifest manifest =
            airtrap::CacheManifest::fromJson(json, "manifest.json");
        (void)manifest.toJson();
    } catch (const airtrap::Error& error) {
        if (error.kind() != airtrap::ErrorKind::CacheCorrupt)
            __builtin_trap();
    }
    return 0;
}
