// airtrap-bench: the dam break of samples/dam_break.json at ~50k, ~120k and ~250k particles with
// support radius = 2 × spacing (SPlisHSPlasH's default, so figures compare), on 1 and 2 threads,
// for a fixed number of steps, the median of --repeat runs. Prints particle-updates per second,
// neighbours per particle, ms per phase and bytes per particle, as a table or (--json) as one JSON
// array.
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
    std::printf("%-16s %9s %3s %6s %10s %7s %9s %8s %8s %8s %8s %8s\n", "scene", "particles", "thr",
                "steps", "Mupd/s", "neigh", "B/part", "ms/step", "neighb", "density", "forces",
                "integr");
}

void printTableRow(const BenchmarkResult& r) {
    const auto phase = [&](const char* name) { return r.phaseMilliseconds.at(name); };
    std::printf("%-16s %9zu %3d %6d %10.3f %7.1f %9.0f %8.2f %8.2f %8.2f %8.2f %8.2f\n",
                r.scene.c_str(), r.particles, r.threads, r.steps, r.particleUpdatesPerSecond / 1e6,
                r.neighborsPerParticle, r.bytesPerParticle, 1000.0 * r.wallSeconds / r.steps,
                phase("neighbours"), phase("density"), phase("forces"), phase("integrate"));
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Airtrap benchmark: WCSPH dam break at several resolutions and thread counts"};
    std::string scenePath = std::string(AIRTRAP_SOURCE_DIR) + "/samples/dam_break.json";
    std::vector<double> sizes = {50000, 120000, 250000};
    std::vector<int> threads = {1, 2};
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
    app.add_flag("--json", json, "Print one JSON array instead of a table");
    CLI11_PARSE(app, argc, argv);

    try {
        const Scene sample = readSceneFile(scenePath);
        nlohmann::json all = nlohmann::json::array();
        if (!json)
            printTableHeader();
        for (double size : sizes) {
            const std::string name =
                "dam_break_" + std::to_string(int(std::lround(size / 1000))) + "k";
            const BenchmarkCase benchmark(name, damBreakWith(sample, size));
            for (int t : threads) {
                const BenchmarkResult result = medianRun(benchmark, t, steps, warmup, repeat);
                if (json)
                    all.push_back(toJson(result));
                else
                    printTableRow(result);
            }
        }
        if (json)
            std::cout << all.dump(2) << "\n";
    } catch (const std::exception& error) {
        std::cerr << "airtrap-bench: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
