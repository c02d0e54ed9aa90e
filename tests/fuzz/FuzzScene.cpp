// libFuzzer target: the scene reader and the validator behind it (sceneFromText, then
// SceneCheck), as `airtrap-cli validate` runs them. An invalid scene is an expected outcome; a
// crash, a hang or another kind of error is a finding. Mesh paths resolve against the working
// folder, where scripts/fuzz.sh puts the test meshes.
#include "core/Error.h"
#include "scene/SceneJson.h"
#include "sim/SceneCheck.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        airtrap::Scene scene = airtrap::sceneFromText(text, "fuzz.json");
        scene.sourcePath = "fuzz.json";
        (void)airtrap::SceneCheck::run(scene);
    } catch (const airtrap::Error& error) {
        const airtrap::ErrorKind kind = error.kind();
        if (kind != airtrap::ErrorKind::InvalidScene && kind != airtrap::ErrorKind::InvalidInput)
            __builtin_trap();
    }
    return 0;
}
