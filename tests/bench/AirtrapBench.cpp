// airtrap-bench: the dam break of samples/dam_break.json at ~50k, ~120k and ~250k particles with
// support radius = 2 × spacing (SPlisHSPlasH's default, so figures compare), on 1 and 2 threads,
// for a fixed number of steps, the median of --repeat runs. Then the cost of two-way coupling:
// samples/diving_bunny.json with the bunny plunging into the pool against the same pool without
// it. Prints particle-updates per second, neighbours per particle, ms per phase and bytes per
// particle, as a table or (--json) as one JSON array.
#include "BenchmarkCase.h"
#include "scene/SceneJson.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

using namespace airtrap;
using namespace airtrap::bench;

namespace {

//! The sample dam break with the spacing chosen so its water holds about `particles`.
Scene damBreakWith(const Scene& sample, double particles) {
    Scene scene = sample;
    double waterVolume = 0.0;
    for (const FluidBlock& block : scene.fluidBlocks)
        waterVolume += (block.max - block.min).prod();
    scene.solver.particleSpacing = std::cbrt(waterVolume / particles);
    scene.solver.supportFactor = 2.0;
    return scene;
}

//! The diving-bunny pool at about `particles`, with the bunny already half-way into the water
//! and plunging at 1 m/s, so every measured step couples; or the same pool without it.
Scene divingBunnyWith(const Scene& sample, double particles, bool withBunny) {
    Scene scene = damBreakWith(sample, particles);
    if (!withBunny) {
        scene.bodies.clear();
        return scene;
    }
    RigidBodySettings& bunny = scene.bodies.at(0);
    const double poolTop = scene.fluidBlocks.at(0).max.y();
    bunny.position.y() = poolTop - 0.1;
    bunny.linearVelocity = Vec3d(0.0, -1.0, 0.0);
    return scene;
}

//! Shared machines are noisy: the median of several runs is the figure that repeats.
BenchmarkResult medianRun(const BenchmarkCase& benchmark, int threads, int steps, int warmup,
                          int repeat) {
    std::vector<BenchmarkResult> runs;
    for (int r = 0; r < repeat; ++r)
        runs.push_back(benchmark.run(threads, steps, warmup));
    std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) {
        return a.particleUpdatesPerSecond < b.particleUpdatesPerSecond;
    });
    return runs[runs.size() / 2];
}

nlohmann::json toJson(const BenchmarkResult& r) {
    nlohmann::json phases = nlohmann::json::object();
    for (const auto& [name, ms] : r.phaseMilliseconds)
        phases[name] = ms;
    return {{"scene", r.scene},
            {"particles", r.particles},
            {"threads", r.threads},
            {"steps", r.steps},
            {"particle_updates_per_second", r.particleUpdatesPerSecond},
            {"neighbors_per_particle", r.neighborsPerParticle},
            {"bytes_per_particle", r.bytesPerParticle},
            {"engine_bytes_per_particle", r.engineBytesPerParticle},
            {"ms_per_step", 1000.0 * r.wallSeconds / r.steps},
            {"phase_ms", phases}};
}

void printTableHeader() {
    std::printf("%-18s %9s %3s %6s %10s %7s %9s %8s %8s %8s %8s %8s %8s\n", "scene", "particles",
                "thr", "steps", "Mupd/s", "neigh", "B/part", "ms/step", "neighb", "density",
                "forces", "bodies", "integr");
}

void printTableRow(const BenchmarkResult& r) {
    const auto phase = [&](const char* name) { return r.phaseMilliseconds.at(name); };
    std::printf("%-18s %9zu %3d %6d %10.3f %7.1f %9.0f %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f\n",
                r.scene.c_str(), r.particles, r.threads, r.steps, r.particleUpdatesPerSecond / 1e6,
                r.neighborsPerParticle, r.bytesPerParticle, 1000.0 * r.wallSeconds / r.steps,
                phase("neighbours"), phase("density"), phase("forces"), phase("bodies"),
                phase("integrate"));
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Airtrap benchmark: WCSPH dam break at several resolutions and thread counts"};
    std::string scenePath = std::string(AIRTRAP_SOURCE_DIR) + "/samples/dam_break.json";
    std::vector<double> sizes = {50000, 120000, 250000};
    std::vector<int> threads = {1, 2};
    std::string couplingPath = std::string(AIRTRAP_SOURCE_DIR) + "/samples/diving_bunny.json";
    std::vector<double> couplingSizes = {50000};
    int steps = 50;
    int warmup = 5;
    int repeat = 3;
    bool json = false;
    app.add_option("--scene", scenePath, "Scene to measure (its fluid blocks set the volume)");
    app.add_option("--particles", sizes, "Target particle counts")->delimiter(',');
    app.add_option("--threads", threads, "Thread counts")->delimiter(',');
    app.add_option("--steps", steps, "Measured steps per run")->check(CLI::PositiveNumber);
    app.add_option("--warmup", warmup, "Unmeasured steps before measuring");
    app.add_option("--repeat", repeat, "Runs per configuration; the median one is reported")
        ->check(CLI::PositiveNumber);
    app.add_option("--coupling-scene", couplingPath, "Scene with one body, for the coupling cost");
    app.add_option("--coupling-particles", couplingSizes,
                   "Particle counts of the coupling cases (empty: none)")
        ->delimiter(',');
    app.add_flag("--json", json, "Print one JSON array instead of a table");
    CLI11_PARSE(app, argc, argv);

    try {
        const Scene sample = readSceneFile(scenePath);
        std::vector<BenchmarkCase> cases;
        const auto thousands = [](double size) {
            return std::to_string(int(std::lround(size / 1000))) + "k";
        };
        for (double size : sizes)
            cases.emplace_back("dam_break_" + thousands(size), damBreakWith(sample, size));
        if (!couplingSizes.empty()) {
            const Scene bunny = readSceneFile(couplingPath);
            for (double size : couplingSizes) {
                cases.emplace_back("pool_" + thousands(size), divingBunnyWith(bunny, size, false));
                cases.emplace_back("diving_bunny_" + thousands(size),
                                   divingBunnyWith(bunny, size, true));
            }
        }
        nlohmann::json all = nlohmann::json::array();
        if (!json)
            printTableHeader();
        for (const BenchmarkCase& benchmark : cases)
            for (int t : threads) {
                const BenchmarkResult result = medianRun(benchmark, t, steps, warmup, repeat);
                if (json)
                    all.push_back(toJson(result));
                else
                    printTableRow(result);
            }
        if (json)
            std::cout << all.dump(2) << "\n";
    } catch (const std::exception& error) {
        std::cerr << "airtrap-bench: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
