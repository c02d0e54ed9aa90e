// A single bubble in still water rises at its capped Stokes speed (paper eq. 5, docs/VALIDATION.md
// "Bubble rise"): after it has settled, its mean vertical speed lies within 15 % of min(2/9 g R²/ν,
// cap).
#include "BubbleTestSupport.h"
#include "support/SceneBuilder.h"
#include "support/TestMain.h"

#include <QtTest>

using namespace airtrap;
using airtrap::test::SceneBuilder;

namespace {

Scene tallStillTank() {
    return SceneBuilder()
        .spacing(0.02)
        .maxSpeed(1.5)
        .tank({0.4, 1.0, 0.4}, 0.2)
        .water({0.0, 0.0, 0.0}, {0.4, 0.9, 0.4})
        .bubbles(false) // only the bubble placed by the test
        .build();
}

} // namespace

class TestBubbleRise : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void risesAtCappedStokesSpeed() {
        Scene scene = tallStillTank();
        scene.bubbles.maxRiseSpeed = 0.25;
        const double radius = 0.04;
        auto simulation =
            test::simulationWithBubbles(scene, {test::bubbleAt(0, Vec3d(0.2, 0.2, 0.2), radius)});
        const double target = 0.25; // 2/9 g R²/ν = 3490 m/s for R = 4 cm: the cap holds

        double startHeight = 0.0;
        double startTime = 0.0;
        while (simulation->state().time < 0.9) {
            simulation->step(1.0);
            QCOMPARE(simulation->state().bubbles.size(), std::size_t(1));
            const double t = simulation->state().time;
            if (startTime == 0.0 && t >= 0.3) {
                startTime = t;
                startHeight = simulation->state().bubbles[0].body.position.y();
            }
        }
        const BubbleState& bubble = simulation->state().bubbles[0];
        const double speed =
            (bubble.body.position.y() - startHeight) / (simulation->state().time - startTime);
        qInfo("mean rise speed over 0.3–0.9 s %.4f m/s (target %.4f), now at y = %.3f, drift "
              "%.4f m",
              speed, target, bubble.body.position.y(),
              (bubble.body.position - Vec3d(0.2, bubble.body.position.y(), 0.2)).norm());
        QVERIFY2(std::abs(speed / target - 1.0) < 0.15,
                 qPrintable(QString("rise speed %1 m/s, target %2").arg(speed).arg(target)));
    }
};

AIRTRAP_TEST_APPLESS(TestBubbleRise)
#include "TestBubbleRise.moc"
