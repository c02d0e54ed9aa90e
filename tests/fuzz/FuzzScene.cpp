// libFuzzer target: the scene reader and the validator behind it (sceneFromText, then
// SceneCheck), as `airtrap-cli validate` runs them. An invalid scene is an expected outcome; a
// crash, a hang or another kind of error is a finding. Mesh paths resolve against the working
// folder, where scripts/fuzz.sh puts the test meshes.
#include "core/Error.h"
#include "scene/SceneJson.h"
#include "scene/SceneValidator.h"
#include "sim/SceneCheck.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace {

//! Above this many water particles the body placement check is left out. It visits every
//! particle of the fluid blocks: work bounded by the particle limit, 1.2 s for 3 million in a
//! release build but 28 s under this build's instrumentation, which the 10-s limit per input
//! would report as a hang (docs/TESTING.md "Fuzzing").
constexpr double kPlacementCheckParticles = 2e5;

double waterParticles(const airtrap::Scene& scene) {
    const double spacing = scene.solver.particleSpacing;
    double particles = 0.0;
    for (const airtrap::FluidBlock& block : scene.fluidBlocks)
        particles += (block.max - block.min).cwiseMax(0.0).prod() / (spacing * spacing * spacing);
    for (const airtrap::InflowEmitterSettings& emitter : scene.emitters)
        particles += emitter.maxParticles;
    return particles;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        airtrap::Scene scene = airtrap::sceneFromText(text, "fuzz.json");
        scene.sourcePath = "fuzz.json";
        if (waterParticles(scene) <= kPlacementCheckParticles)
            (void)airtrap::SceneCheck::run(scene);
        else
            (void)airtrap::SceneValidator::check(scene);
    } catch (const airtrap::Error& error) {
        const airtrap::ErrorKind kind = error.kind();
        if (kind != airtrap::ErrorKind::InvalidScene && kind != airtrap::ErrorKind::InvalidInput)
            __builtin_trap();
    }
    return 0;
}
