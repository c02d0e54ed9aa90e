// The two bubble samples do what they are for (paper §5, Figs. 4 and 5), at a coarser spacing so
// that the test stays short:
//  - samples/pouring.json: the jet traps air in the pool; the bubbles rise, and bubbles are
//    deleted at the surface (floating rule);
//  - samples/diving_bunny.json: the plunging bunny traps air in its wake, and no bubble is ever
//    created inside the closed mesh.
#include "core/Interrupter.h"
#include "scene/SceneJson.h"
#include "sim/Simulation.h"
#include "sph/WcsphSolver.h"
#include "support/TestMain.h"

#include <QtTest>
#include <map>
#include <set>

using namespace airtrap;

namespace {

Scene sample(const char* name) {
    Scene scene = readSceneFile(std::string(AIRTRAP_SOURCE_DIR "/samples/") + name);
    scene.solver.particleSpacing = 0.025;
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
        Interrupter never;
        // Height of each bubble when first and last seen.
        std::map<std::uint32_t, std::pair<double, double>> heights;
        while (simulation.frame() < scene.frames.endFrame) {
            simulation.advanceFrame(never);
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
        qInfo("created %u, risen by two spacings or more %d, deleted age %llu floating %llu "
              "overlap %llu impact %llu, alive %zu",
              state.nextBubbleId, risen, (unsigned long long)state.bubblesDeleted.deleted[0],
              (unsigned long long)state.bubblesDeleted.deleted[1],
              (unsigned long long)state.bubblesDeleted.deleted[2],
              (unsigned long long)state.bubblesDeleted.deleted[3], state.bubbles.size());
        QVERIFY2(state.nextBubbleId >= 5, "the jet trapped too little air");
        QVERIFY2(risen >= 2, "the bubbles did not rise");
        QVERIFY2(state.bubblesDeleted.deleted[BubbleTally::Floating] >= 1,
                 "no bubble popped at the surface");
    }

    void divingBunnyTrapsAirInItsWakeNotInside() {
        Scene scene = sample("diving_bunny.json");
        scene.frames.endFrame = 24;
        QVERIFY(scene.bubbles.enabled);
        Simulation simulation(scene);
        Interrupter never;
        // The bunny is the scene's only body, the last before the bubbles' bodies.
        const std::size_t bunnyIndex = simulation.solver().firstBubbleBody() - 1;
        std::set<std::uint32_t> checked;
        double farthest = 0.0; // from the bunny, in its bounding radii, where a bubble was made
        while (simulation.frame() < scene.frames.endFrame) {
            simulation.advanceFrame(never);
            const RigidBody& bunny = simulation.solver().bodies()[bunnyIndex];
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
        QVERIFY2(checked.size() >= 1, "no air trapped in the wake");
        QVERIFY2(farthest < 3.0, "bubbles made away from the bunny: not its wake");
    }
};

AIRTRAP_TEST_APPLESS(TestSampleBubbles)
#include "TestSampleBubbles.moc"
