#pragma once
// Reads a scene for validate and bake: the file, then the `--set` overrides, then the cross-field
// checks, so that a bad scene is refused before anything is written.
#include "scene/Scene.h"

#include <cstddef>
#include <string>
#include <vector>

namespace airtrap::cli {

struct LoadedScene {
    Scene scene;
    std::vector<std::string> warnings;
    std::vector<std::string> notes;
};

//! How many water particles the fluid blocks fill at t = 0.
struct ParticleEstimate {
    std::size_t count = 0;
    //! False when obstacles or overlapping blocks remove lattice points the sum still counts.
    bool exact = true;
    //! Particles the emitters add by the end frame (exact: emission is a function of time).
    std::size_t emitted = 0;
};

class SceneLoader {
public:
    //! Throws Error(Io) when the file cannot be read, Error(InvalidScene) when the file, an
    //! override or a cross-field rule is wrong (every message names the file or `--set`).
    static LoadedScene load(const std::string& path, const std::vector<std::string>& overrides);

    //! The lattice count of every fluid block (as SceneSetup fills them), without building
    //! the simulation: fast even for scenes of millions of particles.
    static ParticleEstimate estimateParticles(const Scene& scene);
};

} // namespace airtrap::cli
