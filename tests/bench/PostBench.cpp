// airtrap-post-bench: the render outputs' cost against the simulation's (docs/PERFORMANCE.md).
// Bakes the dam break at about --particles, with trapped air bubbles unless --no-bubbles, into a
// scratch cache, then times the post stage (water level set and free-surface mesh, stored beside
// the cache; then the sub-grid bubbles, timed on their own) and the OBJ and VDB exports of the
// same frames, and prints seconds per frame of each beside the bake's.
#include "DamBreakScene.h"
#include "bake/Baker.h"
#include "cache/FrameCache.h"
#include "core/ThreadLimit.h"
#include "io/SequenceExporter.h"
#include "post/PostStage.h"
#include "scene/SceneJson.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

using namespace airtrap;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Timing {
    double bakePerFrame = 0.0;        //!< simulation wall seconds per frame (steps only)
    double postPerFrame = 0.0;        //!< both passes
    double subgridPerFrame = 0.0;     //!< the sub-grid bubbles' pass alone
    std::uint32_t subgridBubbles = 0; //!< in the last frame
    double objPerFrame = 0.0;
    double vdbPerFrame = 0.0;
    std::size_t particles = 0;
};

double exportSeconds(const FrameCache& cache, const Scene& scene, ExportFormat format,
                     const std::string& outDir, const std::vector<int>& frames) {
    Interrupter interrupter;
    SequenceExporter exporter(cache, scene, {format, outDir, UpAxis::Y});
    return exporter.run(frames, interrupter).seconds / double(frames.size());
}

Timing measure(const Scene& scene, int lastFrame, const std::string& dir) {
    Timing timing;
    Baker baker(scene, {.cacheDir = dir, .overwrite = true, .lastFrame = lastFrame});
    double stepSeconds = 0.0;
    baker.onFrame([&](int frame, const FrameStats& stats) {
        if (frame > 1)
            stepSeconds += stats.wallSeconds;
    });
    Interrupter interrupter;
    baker.run(interrupter);
    timing.bakePerFrame = stepSeconds / double(lastFrame - 1);

    const FrameCache cache = FrameCache::open(dir);
    const std::vector<int> frames = cache.frames();
    timing.particles = cache.readFrame(frames.back()).state.fluid.size();
    PostStage post(cache, scene);
    const auto start = std::chrono::steady_clock::now();
    const PostReport report = post.run(frames, interrupter);
    timing.postPerFrame = secondsSince(start) / double(frames.size());
    timing.subgridPerFrame = report.subgrid.seconds / double(frames.size());
    timing.subgridBubbles = report.subgrid.lastFrameBubbles;
    timing.objPerFrame = exportSeconds(cache, scene, ExportFormat::Obj, dir + "/obj", frames);
    timing.vdbPerFrame = exportSeconds(cache, scene, ExportFormat::Vdb, dir + "/vdb", frames);
    return timing;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Airtrap post benchmark: post and export seconds per frame against the bake's"};
    std::string scenePath = std::string(AIRTRAP_SOURCE_DIR) + "/samples/dam_break.json";
    double particles = 250000;
    int frames = 10;
    int threads = 2;
    std::string dir = (std::filesystem::temp_directory_path() / "airtrap-post-bench").string();
    bool json = false;
    bool noBubbles = false;
    app.add_option("--scene", scenePath, "Scene to bake (its fluid blocks set the volume)");
    app.add_option("--particles", particles, "Target particle count");
    app.add_option("--frames", frames, "Frames to bake, post and export")
        ->check(CLI::Range(2, 10000));
    app.add_option("--threads", threads, "Worker threads")->check(CLI::Range(1, 1024));
    app.add_option("--dir", dir, "Scratch cache folder (replaced)");
    app.add_flag("--json", json, "Print one JSON object instead of a line");
    app.add_flag("--no-bubbles", noBubbles, "Bake without trapped air bubbles (and so sub-grid)");
    CLI11_PARSE(app, argc, argv);

    try {
        const ThreadLimit limit(threads);
        Scene scene = bench::damBreakWith(readSceneFile(scenePath), particles);
        scene.bubbles.enabled = !noBubbles;
        const Timing t = measure(scene, frames, dir);
        const double postShare = 100.0 * t.postPerFrame / t.bakePerFrame;
        const double subgridShare = 100.0 * t.subgridPerFrame / t.bakePerFrame;
        if (json) {
            const nlohmann::json result = {{"scene", "dam_break"},
                                           {"particles", t.particles},
                                           {"threads", threads},
                                           {"frames", frames},
                                           {"bake_seconds_per_frame", t.bakePerFrame},
                                           {"post_seconds_per_frame", t.postPerFrame},
                                           {"obj_export_seconds_per_frame", t.objPerFrame},
                                           {"vdb_export_seconds_per_frame", t.vdbPerFrame},
                                           {"post_percent_of_bake", postShare},
                                           {"subgrid_seconds_per_frame", t.subgridPerFrame},
                                           {"subgrid_percent_of_bake", subgridShare},
                                           {"subgrid_bubbles_last_frame", t.subgridBubbles}};
            std::printf("%s\n", result.dump(2).c_str());
        } else {
            std::printf("dam break, %zu particles, %d threads, frames 1-%d: bake %.2f s/frame, "
                        "post %.2f s/frame (%.1f %% of the bake; sub-grid %.3f s/frame, %.2f %%, "
                        "%u bubbles in the last frame), export obj %.2f s/frame, vdb %.2f "
                        "s/frame\n",
                        t.particles, threads, frames, t.bakePerFrame, t.postPerFrame, postShare,
                        t.subgridPerFrame, subgridShare, t.subgridBubbles, t.objPerFrame,
                        t.vdbPerFrame);
        }
        std::filesystem::remove_all(dir);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "airtrap-post-bench: %s\n", error.what());
        return 1;
    }
    return 0;
}
