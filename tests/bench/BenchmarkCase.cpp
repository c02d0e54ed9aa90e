#include "BenchmarkCase.h"

#include "ProcessMemory.h"
#include "core/ThreadLimit.h"
#include "sim/Simulation.h"

#include <chrono>
#include <cmath>

namespace airtrap::bench {

namespace {

//! Mean number of water neighbours within the support radius (excluding the particle itself),
//! counted over a sample of particles.
double meanNeighbors(const PressureSolver& solver, const ParticleSet& fluid) {
    const float radius2 = solver.kernel().supportRadius() * solver.kernel().supportRadius();
    const std::size_t stride = std::max<std::size_t>(1, fluid.size() / 2000);
    std::size_t pairs = 0, sampled = 0;
    for (std::size_t i = 0; i < fluid.size(); i += stride, ++sampled)
        solver.grid().forEachNeighborRange(
            fluid.positions[i], solver.kernel().supportRadius(), [&](auto begin, auto end) {
                for (auto j = begin; j < end; ++j)
                    pairs +=
                        j != i && (fluid.positions[i] - fluid.positions[j]).squaredNorm() < radius2;
            });
    return sampled ? double(pairs) / double(sampled) : 0.0;
}

} // namespace

BenchmarkResult BenchmarkCase::run(int threads, int steps, int warmupSteps) const {
    ThreadLimit limit(threads);
    ProcessMemory::resetPeak();
    const std::size_t baseline = ProcessMemory::residentBytes();

    Simulation simulation = start_ ? Simulation(scene_, *start_) : Simulation(scene_);
    const PressureSolver& solver = simulation.solver();
    const double noFrameLimit = 1.0e9;
    for (int s = 0; s < warmupSteps; ++s)
        simulation.step(noFrameLimit);
    simulation.phases().reset();

    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s)
        simulation.step(noFrameLimit);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    BenchmarkResult result;
    result.scene = name_;
    const ParticleSet& fluid = simulation.state().fluid;
    result.particles = fluid.size();
    result.threads = limit.threads();
    result.steps = steps;
    result.wallSeconds = wall;
    result.bubbles = simulation.state().bubbles.size();
    result.particleUpdatesPerSecond = double(result.particles) * steps / wall;
    result.neighborsPerParticle = meanNeighbors(solver, fluid);
    const double n = double(std::max<std::size_t>(1, result.particles));
    result.bytesPerParticle = double(ProcessMemory::peakResidentBytes() - baseline) / n;
    result.engineBytesPerParticle = double(solver.allocatedBytes() + fluid.allocatedBytes()) / n;
    for (int phase = 0; phase < StepPhases::Count; ++phase)
        result.phaseMilliseconds[std::string(StepPhases::kNames[phase])] =
            1000.0 * simulation.phases().seconds(static_cast<StepPhases::Phase>(phase)) / steps;
    return result;
}

} // namespace airtrap::bench
