// airtrap-bench: the dam break of samples/dam_break.json at ~50k, ~120k and ~250k particles with
// support radius = 2 × spacing (SPlisHSPlasH's default, so figures compare), on 1 and 2 threads,
// for a fixed number of steps, the median of --repeat runs. Then the cost of two-way coupling:
// samples/diving_bunny.json with the bunny plunging into the pool against the same pool without
// it. Then the cost of the trapped air bubbles on samples/pouring.json, twice: as the paper
// measured it, a whole bake with bubbles against one without; and per step from the moment the jet
// has trapped the most air, with bubbles on and off (the same water, without the bubbles' bodies,
// pocket searches and rules): each side's own figures, and the overhead from the two stepped in
// turn (BubbleStepComparison); --bubble-scene and --bubble-method measure another bubble scene or
// solver (DFSPH's jets trap air in samples/bubble_column.json, not in the pouring sample's shallow
// pool). Prints particle-updates per second, neighbours
// per particle, ms per phase and bytes per particle, as a table or (--json) as one JSON array.
//
// --sim-seconds S (1 when given without a value) is the other mode: instead of fixed step counts,
// it bakes S simulated seconds of samples/bench/peer_dam_break.json (SPlisHSPlasH's DamBreakModel,
// 117,649 particles) with each pressure solver on each thread count: the wall seconds per
// simulated second an artist waits, with steps, iterations per solve, ms per phase and bytes per
// particle.
#include "BenchmarkCase.h"
#include "BubbleBakeComparison.h"
#include "BubbleStepComparison.h"
#include "DamBreakScene.h"
#include "SimulatedSecondsCase.h"
#include "scene/SceneJson.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

using namespace airtrap;
using namespace airtrap::bench;

namespace {

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

//! The pouring sample at about `particles` (its pool's), with bubbles.
Scene pouringWith(const Scene& sample, double particles) {
    Scene scene = damBreakWith(sample, particles);
    scene.bubbles.enabled = true;
    // The jet's layers and budget scale with the spacing: keep the poured volume.
    const double scale = std::pow(sample.solver.particleSpacing / scene.solver.particleSpacing, 3);
    for (InflowEmitterSettings& emitter : scene.emitters)
        emitter.maxParticles = int(std::lround(emitter.maxParticles * scale));
    return scene;
}

void printBakeComparison(const std::string& name, const BubbleBakeResult& bake) {
    std::printf("%s, whole bake of %d frames (%d thr, %zu particles at the end): %.1f s with "
                "bubbles (%llu steps, %.3f ms/step) vs %.1f s without (%llu steps, %.3f ms/step), "
                "overhead %+.2f %%; bubble phases %.2f %% of the bake; %zu bubbles created, at "
                "most %zu alive\n",
                name.c_str(), bake.frames, bake.threads, bake.particles, bake.secondsOn,
                static_cast<unsigned long long>(bake.stepsOn), bake.msPerStepOn(), bake.secondsOff,
                static_cast<unsigned long long>(bake.stepsOff), bake.msPerStepOff(),
                bake.overheadPercent(), 100.0 * bake.bubblePhaseSeconds / bake.secondsOn,
                bake.bubblesCreated, bake.mostBubblesAlive);
    std::fflush(stdout);
}

nlohmann::json toJson(const std::string& name, const BubbleBakeResult& bake) {
    return {{"scene", name},
            {"frames", bake.frames},
            {"threads", bake.threads},
            {"particles", bake.particles},
            {"seconds_with_bubbles", bake.secondsOn},
            {"seconds_without_bubbles", bake.secondsOff},
            {"steps_with_bubbles", bake.stepsOn},
            {"steps_without_bubbles", bake.stepsOff},
            {"bubble_overhead_percent", bake.overheadPercent()},
            {"bubble_phase_percent", 100.0 * bake.bubblePhaseSeconds / bake.secondsOn},
            {"bubbles_created", bake.bubblesCreated},
            {"most_bubbles_alive", bake.mostBubblesAlive}};
}

//! The same water without bubbles: the baseline the overhead is measured against.
std::pair<Scene, SimulationState> withoutBubbles(std::pair<Scene, SimulationState> run) {
    run.first.bubbles.enabled = false;
    run.second.bubbles.clear();
    return run;
}

double msPerStep(const BenchmarkResult& r) {
    return 1000.0 * r.wallSeconds / r.steps;
}

void printBubbleOverhead(const BubbleStepResult& pair) {
    const auto on = [&](const char* name) { return pair.phaseMillisecondsOn.at(name); };
    std::printf("  bubbles (%zu alive, %d thr): %.3f vs %.3f ms/step, overhead %+.2f %% (%d steps "
                "each, in turn); per step pockets %.4f ms, forces %.4f ms, deletion %.4f ms, "
                "bodies %.4f vs %.4f ms\n",
                pair.bubbles, pair.threads, pair.msPerStepOn, pair.msPerStepOff,
                pair.overheadPercent(), pair.steps, on("bubble_pockets"), on("bubble_forces"),
                on("bubble_deletion"), on("bodies"), pair.phaseMillisecondsOff.at("bodies"));
    std::fflush(stdout);
}

nlohmann::json toJson(const BubbleStepResult& pair) {
    return {{"threads", pair.threads},
            {"steps", pair.steps},
            {"bubbles", pair.bubbles},
            {"ms_per_step_with_bubbles", pair.msPerStepOn},
            {"ms_per_step_without_bubbles", pair.msPerStepOff},
            {"bubble_overhead_percent", pair.overheadPercent()},
            {"phase_ms_with_bubbles", pair.phaseMillisecondsOn},
            {"phase_ms_without_bubbles", pair.phaseMillisecondsOff}};
}

BenchmarkResult median(std::vector<BenchmarkResult> runs) {
    std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) {
        return a.particleUpdatesPerSecond < b.particleUpdatesPerSecond;
    });
    return runs[runs.size() / 2];
}

//! Shared machines are noisy: the median of several runs is the figure that repeats.
BenchmarkResult medianRun(const BenchmarkCase& benchmark, int threads, int steps, int warmup,
                          int repeat) {
    std::vector<BenchmarkResult> runs;
    for (int r = 0; r < repeat; ++r)
        runs.push_back(benchmark.run(threads, steps, warmup));
    return median(std::move(runs));
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
            {"ms_per_step", msPerStep(r)},
            {"bubbles", r.bubbles},
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
                r.neighborsPerParticle, r.bytesPerParticle, msPerStep(r), phase("neighbours"),
                phase("density"), phase("forces"), phase("bodies"), phase("integrate"));
    std::fflush(stdout);
}

void printSimulatedSecondsHeader() {
    std::printf("%-16s %-6s %9s %3s %6s %6s %8s %8s %6s %6s %5s %7s %6s %8s %8s %8s %8s %8s\n",
                "scene", "method", "particles", "thr", "sim s", "steps", "wall s", "s/sim-s",
                "div it", "den it", "uncon", "B/part", "eng B", "ms/step", "neighb", "density",
                "div_sol", "forces");
}

void printSimulatedSecondsRow(const SimulatedSecondsResult& r) {
    const auto phase = [&](const char* name) {
        const auto found = r.phaseMilliseconds.find(name);
        return found == r.phaseMilliseconds.end() ? 0.0 : found->second;
    };
    const double msPerStep = r.steps ? 1000.0 * r.wallSeconds / double(r.steps) : 0.0;
    std::printf(
        "%-16s %-6s %9zu %3d %6.2f %6llu %8.1f %8.1f %6.2f %6.2f %5llu %7.0f %6.0f %8.2f %8.2f "
        "%8.2f %8.2f %8.2f\n",
        r.scene.c_str(), r.method.c_str(), r.particles, r.threads, r.simulatedSeconds,
        static_cast<unsigned long long>(r.steps), r.wallSeconds, r.wallPerSimulatedSecond(),
        r.divergenceIterationsPerStep, r.densityIterationsPerStep,
        static_cast<unsigned long long>(r.unconvergedSteps), r.bytesPerParticle,
        r.engineBytesPerParticle, msPerStep, phase("neighbours"), phase("density"),
        phase("divergence_solve"), phase("forces"));
    std::fflush(stdout);
}

nlohmann::json toJson(const SimulatedSecondsResult& r) {
    return {{"scene", r.scene},
            {"method", r.method},
            {"particles", r.particles},
            {"threads", r.threads},
            {"simulated_seconds", r.simulatedSeconds},
            {"wall_seconds", r.wallSeconds},
            {"wall_seconds_per_simulated_second", r.wallPerSimulatedSecond()},
            {"steps", r.steps},
            {"divergence_iterations_per_step", r.divergenceIterationsPerStep},
            {"density_iterations_per_step", r.densityIterationsPerStep},
            {"unconverged_steps", r.unconvergedSteps},
            {"bytes_per_particle", r.bytesPerParticle},
            {"engine_bytes_per_particle", r.engineBytesPerParticle},
            {"phase_ms", r.phaseMilliseconds}};
}

//! The --sim-seconds mode: `seconds` simulated of `scenePath` per method and thread count.
void runSimulatedSeconds(const std::string& scenePath, double seconds,
                         const std::vector<std::string>& methods, const std::vector<int>& threads,
                         bool json) {
    const Scene sample = readSceneFile(scenePath);
    nlohmann::json all = nlohmann::json::array();
    if (!json)
        printSimulatedSecondsHeader();
    for (const std::string& method : methods) {
        Scene scene = sample;
        scene.solver.method = method;
        const SimulatedSecondsCase bake("peer_dam_break", scene);
        for (int t : threads) {
            const SimulatedSecondsResult result = bake.run(t, seconds);
            if (json)
                all.push_back(toJson(result));
            else
                printSimulatedSecondsRow(result);
        }
    }
    if (json)
        std::cout << all.dump(2) << "\n";
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Airtrap benchmark: WCSPH dam break at several resolutions and thread counts"};
    std::string scenePath = std::string(AIRTRAP_SOURCE_DIR) + "/samples/dam_break.json";
    std::vector<double> sizes = {50000, 120000, 250000};
    std::vector<int> threads = {1, 2};
    std::string couplingPath = std::string(AIRTRAP_SOURCE_DIR) + "/samples/diving_bunny.json";
    std::vector<double> couplingSizes = {50000};
    std::string bubblePath = std::string(AIRTRAP_SOURCE_DIR) + "/samples/pouring.json";
    std::vector<double> bubbleSizes = {50000};
    double bubbleWarmup = 1.0;
    int bubbleFrames = 0;
    int bubbleSteps = 400;
    std::string bubbleMethod; // empty: the bubble scene's own
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
    app.add_option("--bubble-scene", bubblePath, "Scene with bubbles, for their overhead");
    app.add_option("--bubble-particles", bubbleSizes,
                   "Pool particle counts of the bubble cases (empty: none)")
        ->delimiter(',');
    app.add_option("--bubble-warmup", bubbleWarmup,
                   "Simulated seconds into the bake where the per-step bubble cases start");
    app.add_option("--bubble-frames", bubbleFrames,
                   "Frames of the whole-bake bubble comparison (0: the scene's end frame)");
    app.add_option("--bubble-method", bubbleMethod,
                   "Pressure solver of the bubble cases (default: the bubble scene's own)")
        ->check(CLI::IsMember({"wcsph", "dfsph"}));
    app.add_option("--bubble-steps", bubbleSteps,
                   "Steps of each side when the per-step bubble cases are stepped in turn")
        ->check(CLI::PositiveNumber);
    app.add_flag("--json", json, "Print one JSON array instead of a table");
    std::string simSecondsText;
    CLI::Option* simSecondsOption =
        app.add_option("--sim-seconds", simSecondsText,
                       "Bake this many simulated seconds (1 if no value) of --sim-scene with "
                       "each --methods, instead of the per-step cases")
            ->expected(0, 1);
    std::string simScenePath =
        std::string(AIRTRAP_SOURCE_DIR) + "/samples/bench/peer_dam_break.json";
    app.add_option("--sim-scene", simScenePath, "Scene of the --sim-seconds mode");
    std::vector<std::string> methods = {"dfsph", "wcsph"};
    app.add_option("--methods", methods, "Pressure solvers of the --sim-seconds mode")
        ->delimiter(',')
        ->check(CLI::IsMember({"wcsph", "dfsph"}));
    CLI11_PARSE(app, argc, argv);

    if (simSecondsOption->count() > 0) {
        try {
            const double seconds = simSecondsText.empty() ? 1.0 : std::stod(simSecondsText);
            if (!(seconds > 0.0))
                throw std::invalid_argument("expected a positive number of seconds");
            runSimulatedSeconds(simScenePath, seconds, methods, threads, json);
        } catch (const std::exception& error) {
            std::cerr << "airtrap-bench: --sim-seconds " << simSecondsText << ": " << error.what()
                      << "\n";
            return 1;
        }
        return 0;
    }

    try {
        const Scene sample = readSceneFile(scenePath);
        std::vector<BenchmarkCase> cases;
        const auto thousands = [](double size) {
            return std::to_string(int(std::lround(size / 1000))) + "k";
        };
        // An empty option ("--particles ''") reads as one 0: no case.
        const auto wanted = [](std::vector<double>& list) {
            std::erase_if(list, [](double size) { return !(size > 0.0); });
        };
        wanted(sizes);
        wanted(couplingSizes);
        wanted(bubbleSizes);
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
        struct BubbleCases {
            BenchmarkCase off;
            BenchmarkCase on;
            BubbleStepComparison inTurn;
        };
        std::vector<BubbleCases> bubbleCases;
        if (!bubbleSizes.empty()) {
            const Scene pouring = readSceneFile(bubblePath);
            for (double size : bubbleSizes) {
                Scene scene = pouringWith(pouring, size);
                if (!bubbleMethod.empty())
                    scene.solver.method = bubbleMethod;
                std::string name =
                    std::filesystem::path(bubblePath).stem().string() + "_" + thousands(size);
                if (!bubbleMethod.empty())
                    name += "_" + bubbleMethod;
                const int frames = bubbleFrames > 0 ? bubbleFrames : scene.frames.endFrame;
                BubbleBakeResult bake = BubbleBakeComparison(scene, frames).run(0, bubbleWarmup);
                if (json)
                    all.push_back(toJson(name, bake));
                else
                    printBakeComparison(name, bake);
                if (!bake.snapshot)
                    throw std::runtime_error("--bubble-warmup " + std::to_string(bubbleWarmup) +
                                             " s is past the bake's end; expected at most " +
                                             std::to_string(frames / scene.frames.fps) + " s");
                auto on = std::make_pair(scene, std::move(*bake.snapshot));
                auto off = withoutBubbles(on);
                bubbleCases.push_back({BenchmarkCase(name + "_off", off.first, off.second),
                                       BenchmarkCase(name + "_on", on.first, on.second),
                                       BubbleStepComparison(on.first, on.second)});
            }
        }
        if (!json)
            printTableHeader();
        const auto measure = [&](const BenchmarkCase& benchmark, int t) {
            const BenchmarkResult result = medianRun(benchmark, t, steps, warmup, repeat);
            if (json)
                all.push_back(toJson(result));
            else
                printTableRow(result);
            return result;
        };
        for (const BenchmarkCase& benchmark : cases)
            for (int t : threads)
                measure(benchmark, t);
        for (const BubbleCases& bubbles : bubbleCases)
            for (int t : threads) {
                measure(bubbles.off, t);
                measure(bubbles.on, t);
                const BubbleStepResult pair = bubbles.inTurn.run(t, bubbleSteps, warmup);
                if (json)
                    all.back()["stepped_in_turn"] = toJson(pair);
                else
                    printBubbleOverhead(pair);
            }
        if (json)
            std::cout << all.dump(2) << "\n";
    } catch (const std::exception& error) {
        std::cerr << "airtrap-bench: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
