#include "ValidateCommand.h"

#include "SceneLoader.h"

#include <iostream>
#include <sstream>
#include <string>

namespace airtrap::cli {

void ValidateCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand("validate", "Check a scene file (and --set overrides) without "
                                             "baking");
    app_->add_option("SCENE", scenePath_, "Scene file (JSON)")->required();
    app_->add_option("--set", overrides_,
                     "Override a scene value, e.g. solver.particle_spacing=0.02 (repeatable)")
        ->allow_extra_args(false);
}

ExitCode ValidateCommand::run() {
    const LoadedScene loaded = SceneLoader::load(scenePath_, overrides_);
    for (const std::string& warning : loaded.warnings)
        std::cerr << "warning: " << warning << '\n';
    for (const std::string& note : loaded.notes)
        std::cerr << "note: " << note << '\n';
    const ParticleEstimate particles = SceneLoader::estimateParticles(loaded.scene);
    std::ostringstream fps;
    fps << loaded.scene.frames.fps;
    std::cout << "OK: " << scenePath_ << " (" << (particles.exact ? "" : "about ")
              << particles.count << " particles"
              << (particles.emitted > 0
                      ? " + " + std::to_string(particles.emitted) + " emitted by the end frame"
                      : std::string())
              << ", " << loaded.scene.frames.endFrame << " frames at " << fps.str() << " fps)\n";
    return ExitCode::Success;
}

} // namespace airtrap::cli
