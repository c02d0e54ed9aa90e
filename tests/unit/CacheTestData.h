#pragma once
// Random but reproducible simulation states for the cache tests.
#include "core/Error.h"
#include "sim/FrameStats.h"
#include "sim/SimulationState.h"

#include <functional>
#include <optional>
#include <random>

namespace airtrap::testing {

inline SimulationState randomState(int frame, std::size_t particles, unsigned seed) {
    std::mt19937 random(seed);
    // Finite values only: NaN != NaN would make operator== useless for the round trip.
    std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
    std::uniform_real_distribution<double> scalar(1e-6, 1e3);
    SimulationState state;
    state.frame = frame;
    state.time = scalar(random);
    state.steps = random() * 1000ull + 7;
    state.lastTimeStep = scalar(random) * 1e-6;
    state.lastMaxAcceleration = scalar(random);
    state.nextParticleId = static_cast<std::uint32_t>(particles + 11);
    for (std::size_t i = 0; i < particles; ++i)
        state.fluid.push(Vec3f(coordinate(random), coordinate(random), coordinate(random)),
                         Vec3f(coordinate(random), coordinate(random), coordinate(random)),
                         1000.0f + coordinate(random), static_cast<std::uint32_t>(random()));
    return state;
}

inline FrameStats randomStats(unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> value(0.0, 5.0);
    FrameStats stats;
    stats.wallSeconds = value(random);
    stats.phaseSeconds = {{"neighbours", value(random)},
                          {"density", value(random)},
                          {"forces", value(random)},
                          {"integrate", value(random)}};
    stats.stepsInFrame = 42 + seed;
    stats.maxSpeed = value(random);
    stats.meanDensity = 1000.0 + value(random);
    return stats;
}

//! The Error `action` throws, or nothing when it does not throw.
inline std::optional<Error> errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const Error& error) {
        return error;
    }
    return std::nullopt;
}

} // namespace airtrap::testing
