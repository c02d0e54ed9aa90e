// The two bubble samples do what they are for (paper §5, Figs. 4 and 5), at a coarser spacing so
// that the test stays short:
//  - samples/pouring.json: the jet traps air in the pool; the bubbles rise, pop at the surface
//    (surfaced or floating rule), and at most 2 % of the bubble-frames are out of the water
//    (docs/VALIDATION.md, "Where the bubbles live"); the pool, five spacings deep, does not keep
//    90 % of them in water (an expected failure, with the reason there). WCSPH only, the sample's
//    method: with DFSPH's XSPH viscosity the jet enters the pool without a splash and traps no
//    air (docs/VALIDATION.md "Bubbles with DFSPH");
//  - samples/bubble_column.json, at its own settings for the whole bake, with both methods: the
//    plunging jet drives air deep into the tank, at least 90 % of the bubble-frames are in water,
//    at most 2 % out of it, and in water the bubbles rise through the water around them at their
//    capped Stokes speed;
//  - samples/diving_bunny.json, with both methods: no bubble is ever created inside the closed
//    mesh; the air in the bunny's wake stays open to the air at this resolution (an expected
//    failure).
#include "core/Interrupter.h"
#include "post/BubbleCensus.h"
#include "scene/SceneJson.h"
#include "sim/Simulation.h"
#include "support/SolverMethods.h"
#include "support/TestMain.h"

#include <QtTest>
#include <cmath>
#include <map>
#include <set>

using namespace airtrap;

namespace {

Scene sample(const char* name) {
    Scene scene = readSceneFile(std::string(AIRTRAP_SOURCE_DIR "/samples/") + name);
    scene.solver.particleSpacing = 0.025;
    return scene;
}

//! The sample at its own settings but with `method` ("wcsph" or "dfsph").
Scene sampleWith(const char* name, const QString& method) {
    Scene scene = readSceneFile(std::string(AIRTRAP_SOURCE_DIR "/samples/") + name);
    scene.solver.method = method.toStdString();
    return scene;
}

} // namespace

class TestSampleBubbles : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void pouringTrapsAirThatRisesAndPops() {
        const Scene scene = sample("pouring.json");
        QVERIFY(scene.bubbles.enabled);
        Simulation simulation(scene);
        BubbleCensus census(scene);
        Interrupter never;
        // Height of each bubble when first and last seen.
        std::map<std::uint32_t, std::pair<double, double>> heights;
        while (simulation.frame() < scene.frames.endFrame) {
            simulation.advanceFrame(never);
            census.add(FrameData{simulation.state(), simulation.lastFrameStats()});
            for (const BubbleState& bubble : simulation.state().bubbles) {
                auto [entry, fresh] = heights.try_emplace(bubble.id, bubble.body.position.y(),
                                                          bubble.body.position.y());
                entry->second.second = bubble.body.position.y();
            }
        }
        const SimulationState& state = simulation.state();
        int risen = 0;
        for (const auto& [id, seen] : heights)
            risen += seen.second - seen.first > 2.0 * scene.solver.particleSpacing;
        const BubbleTally& deleted = state.bubblesDeleted;
        const BubbleCensusTotals& where = census.totals();
        qInfo("created %u, risen by two spacings or more %d, deleted age %llu floating %llu "
              "overlap %llu impact %llu surfaced %llu, alive %zu; %llu bubble-frames: in water "
              "%.1f %%, floating %.1f %%, airborne %.1f %%",
              state.nextBubbleId, risen, (unsigned long long)deleted.deleted[BubbleTally::Age],
              (unsigned long long)deleted.deleted[BubbleTally::Floating],
              (unsigned long long)deleted.deleted[BubbleTally::Overlap],
              (unsigned long long)deleted.deleted[BubbleTally::Impact],
              (unsigned long long)deleted.deleted[BubbleTally::Surfaced], state.bubbles.size(),
              (unsigned long long)where.bubbleFrames, 100.0 * where.inWaterShare(),
              100.0 * where.floatingShare(), 100.0 * where.airborneShare());
        QVERIFY2(state.nextBubbleId >= 5, "the jet trapped too little air");
        QVERIFY2(risen >= 2, "the bubbles did not rise");
        QVERIFY2(deleted.deleted[BubbleTally::Floating] + deleted.deleted[BubbleTally::Surfaced] >=
                     1,
                 "no bubble popped at the surface");
        QVERIFY(where.booksBalance);
        QVERIFY2(where.bubbleFrames >= 50, "too few bubble-frames to judge where bubbles live");
        QVERIFY2(where.airborneShare() <= 0.02, "bubbles live out of the water");
        QEXPECT_FAIL("", "bubbles are born under spray in a pool five spacings deep", Continue);
        QVERIFY2(where.inWaterShare() >= 0.9, "fewer than 90 % of the bubble-frames in water");
    }

    void bubbleColumnKeepsItsBubblesInWater_data() { test::addSolverMethodRows(); }
    void bubbleColumnKeepsItsBubblesInWater() {
        QFETCH(QString, method);
        const Scene scene = sampleWith("bubble_column.json", method);
        Simulation simulation(scene);
        BubbleCensus census(scene);
        Interrupter never;
        while (simulation.frame() < scene.frames.endFrame) {
            simulation.advanceFrame(never);
            census.add(FrameData{simulation.state(), simulation.lastFrameStats()});
        }
        const BubbleCensusTotals& where = census.totals();
        qInfo("%llu bubbles made, %llu bubble-frames: in water %.1f %%, floating %.1f %%, "
              "airborne %.1f %%; rise in water %.3f m/s, %.3f relative to the water, of %.3f",
              (unsigned long long)where.created, (unsigned long long)where.bubbleFrames,
              100.0 * where.inWaterShare(), 100.0 * where.floatingShare(),
              100.0 * where.airborneShare(), where.meanRiseSpeedInWater, where.meanSlipSpeedInWater,
              where.meanTargetRiseSpeed);
        QVERIFY(where.booksBalance);
        QVERIFY2(where.bubbleFrames >= 100, "too few bubble-frames to judge where bubbles live");
        QVERIFY2(where.inWaterShare() >= 0.9, "fewer than 90 % of the bubble-frames in water");
        QVERIFY2(where.airborneShare() <= 0.02, "more than 2 % of the bubble-frames airborne");
        // Rising, not drifting: through the water around them at their capped Stokes speed on
        // average, within 25 % (eq. 5 steers the rise relative to the water; the jet's current
        // carries the bubbles down or up on top of it).
        QVERIFY2(std::abs(where.meanSlipSpeedInWater / where.meanTargetRiseSpeed - 1.0) < 0.25,
                 qPrintable(QString("rising %1 m/s through the water, target %2 m/s")
                                .arg(where.meanSlipSpeedInWater)
                                .arg(where.meanTargetRiseSpeed)));
    }

    void divingBunnyTrapsAirInItsWakeNotInside_data() { test::addSolverMethodRows(); }
    void divingBunnyTrapsAirInItsWakeNotInside() {
        QFETCH(QString, method);
        Scene scene = sample("diving_bunny.json");
        scene.solver.method = method.toStdString();
        scene.frames.endFrame = 24;
        QVERIFY(scene.bubbles.enabled);
        Simulation simulation(scene);
        Interrupter never;
        // The bunny is the scene's only body, the last before the bubbles' bodies.
        const std::size_t bunnyIndex = simulation.bodies().firstBubbleBody() - 1;
        std::set<std::uint32_t> checked;
        double farthest = 0.0; // from the bunny, in its bounding radii, where a bubble was made
        while (simulation.frame() < scene.frames.endFrame) {
            simulation.advanceFrame(never);
            const RigidBody& bunny = simulation.bodies().bodies()[bunnyIndex];
            for (const BubbleState& bubble : simulation.state().bubbles) {
                if (!checked.insert(bubble.id).second)
                    continue; // judged where it was created
                const double clearance = bunny.signedDistance(bubble.body.position);
                QVERIFY2(clearance > 0.0,
                         qPrintable(QString("bubble %1 created inside the bunny (%2 m)")
                                        .arg(bubble.id)
                                        .arg(clearance)));
                farthest = std::max(farthest, (bubble.body.position - bunny.position()).norm() /
                                                  bunny.shape().boundingRadius());
            }
        }
        qInfo("%zu bubbles created while the bunny dived, at most %.2f bounding radii from it",
              checked.size(), farthest);
        // The pockets behind the bunny are not under water by the creation rule (docs/METHOD.md):
        // they open to the air above its back. docs/VALIDATION.md, "Where the bubbles live".
        QEXPECT_FAIL("", "the bunny's wake pockets are not under water at this spacing", Continue);
        QVERIFY2(checked.size() >= 1, "no air trapped in the wake");
        QVERIFY2(farthest < 3.0, "bubbles made away from the bunny: not its wake");
    }
};

AIRTRAP_TEST_APPLESS(TestSampleBubbles)
#include "TestSampleBubbles.moc"
