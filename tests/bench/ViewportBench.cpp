// airtrap-viewport-bench: how fast the editor's viewport shows water. The sample dam break's
// initial column at ~50k, ~250k and ~1M particles, given a synthetic swirl so that the speed
// colours vary, is shown in a real ViewportWidget under X; for each count it reports the ms to take
// a new frame (setFrame + the paint that uploads it) and the ms per repaint while the camera
// orbits, both waited out with glFinish, plus the frames per second that gives. A table, or
// (--json) one JSON array. The renderer is printed with the figures: on a machine without a GPU
// they are Mesa llvmpipe's, i.e. software rendering on the CPU.
#include "ViewportDrawBenchmark.h"
#include "scene/SceneJson.h"
#include "sim/Simulation.h"
#include "viewport/ViewportWidget.h"

#include <CLI/CLI.hpp>
#include <QApplication>
#include <QSurfaceFormat>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <regex>
#include <vector>

using namespace airtrap;
using namespace airtrap::bench;

namespace {

//! Angular speed of the swirl about the column's centre; its edge moves at ~4.5 m/s, most of the
//! scene's 6 m/s design speed, so the colours span blue to near white.
constexpr float kSwirlRadiansPerSecond = 8.0f;

//! The sample dam break with the spacing chosen so its water holds about `particles`.
Scene damBreakWith(const Scene& sample, double particles) {
    Scene scene = sample;
    double waterVolume = 0.0;
    for (const FluidBlock& block : scene.fluidBlocks)
        waterVolume += (block.max - block.min).prod();
    scene.solver.particleSpacing = std::cbrt(waterVolume / particles);
    return scene;
}

//! The scene's initial water, spinning about a horizontal axis through its centre with a little
//! sideways wobble: water at rest is all one colour and would leave the colour path untested.
std::shared_ptr<const FrameData> swirlingInitialFrame(const Scene& scene) {
    const Simulation simulation(scene);
    auto frame =
        std::make_shared<FrameData>(FrameData{simulation.state(), simulation.lastFrameStats()});
    ParticleSet& fluid = frame->state.fluid;
    Vec3f centre = Vec3f::Zero();
    for (const Vec3f& p : fluid.positions)
        centre += p;
    centre /= float(std::max<std::size_t>(fluid.size(), 1));
    for (std::size_t i = 0; i < fluid.size(); ++i) {
        const Vec3f r = fluid.positions[i] - centre;
        fluid.velocities[i] = kSwirlRadiansPerSecond * Vec3f(-r.y(), r.x(), 0.0f) +
                              Vec3f(0.0f, 0.0f, 0.5f * std::sin(20.0f * r.x()));
    }
    return frame;
}

bool parseSize(const std::string& text, QSize& size) {
    std::smatch match;
    if (!std::regex_match(text, match, std::regex(R"((\d{2,5})x(\d{2,5}))")))
        return false;
    size = QSize(std::stoi(match[1]), std::stoi(match[2]));
    return true;
}

void printTableHeader(const QString& renderer, const QSize& size) {
    std::printf("renderer: %s\nviewport: %dx%d\n", qPrintable(renderer), size.width(),
                size.height());
    std::printf("%10s %10s %10s %8s\n", "particles", "upload ms", "draw ms", "fps");
}

void printTableRow(const ViewportDrawResult& r) {
    std::printf("%10zu %10.2f %10.2f %8.1f\n", r.particles, r.uploadMilliseconds,
                r.drawMilliseconds, r.framesPerSecond);
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Airtrap viewport benchmark: particle upload and draw times at several counts"};
    std::string scenePath = std::string(AIRTRAP_SOURCE_DIR) + "/samples/dam_break.json";
    std::vector<double> counts = {50000, 250000, 1000000};
    int frames = 30;
    int warmup = 5;
    int uploads = 5;
    std::string sizeText = "1280x720";
    bool json = false;
    app.add_option("--scene", scenePath, "Scene whose initial water is drawn");
    app.add_option("--particles", counts, "Target particle counts")->delimiter(',');
    app.add_option("--frames", frames, "Measured repaints per count")->check(CLI::PositiveNumber);
    app.add_option("--warmup", warmup, "Unmeasured repaints before measuring");
    app.add_option("--uploads", uploads, "Measured uploads per count")->check(CLI::PositiveNumber);
    app.add_option("--size", sizeText, "Viewport size in pixels, WxH");
    app.add_flag("--json", json, "Print one JSON array instead of a table");
    // Parsed before QApplication exists, so that --help works without a display.
    CLI11_PARSE(app, argc, argv);
    QSize size;
    if (!parseSize(sizeText, size)) {
        std::cerr << "airtrap-viewport-bench: --size " << sizeText
                  << ": expected WxH, e.g. 1280x720\n";
        return 2;
    }

    // Before QApplication, as in the editor: Qt's shared contexts must be core profile too.
    QSurfaceFormat::setDefaultFormat(ViewportWidget::surfaceFormat());
    // QApplication keeps references to these: they must outlive it. CLI11 has already checked
    // the arguments, so Qt sees only the program name.
    int qtArgc = 1;
    QApplication qtApp(qtArgc, argv);

    try {
        const Scene sample = readSceneFile(scenePath);
        ViewportDrawBenchmark benchmark(size);
        if (!benchmark.openGlProblem().isEmpty()) {
            std::cerr << "airtrap-viewport-bench: " << qPrintable(benchmark.openGlProblem())
                      << "\n";
            return 1;
        }
        nlohmann::json all = nlohmann::json::array();
        if (!json)
            printTableHeader(benchmark.renderer(), benchmark.viewportSize());
        for (double count : counts) {
            const Scene scene = damBreakWith(sample, count);
            const ViewportDrawResult result =
                benchmark.run(scene, swirlingInitialFrame(scene), uploads, frames, warmup);
            if (json)
                all.push_back({{"particles", result.particles},
                               {"upload_ms", result.uploadMilliseconds},
                               {"draw_ms", result.drawMilliseconds},
                               {"fps", result.framesPerSecond},
                               {"renderer", benchmark.renderer().toStdString()}});
            else
                printTableRow(result);
        }
        if (json)
            std::cout << all.dump(2) << "\n";
    } catch (const std::exception& error) {
        std::cerr << "airtrap-viewport-bench: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
