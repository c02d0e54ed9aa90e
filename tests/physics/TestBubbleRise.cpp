// A single bubble in still water rises at its capped Stokes speed (paper eq. 5, docs/VALIDATION.md
// "Bubble rise"): after it has settled, its mean vertical speed lies within 15 % of min(2/9 g R²/ν,
// cap).
#include "BubbleTestSupport.h"
#include "support/SceneBuilder.h"
#include "support/SolverMethods.h"
#include "support/TestMain.h"

#include <QtTest>
#include <map>

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
    void risesAtCappedStokesSpeed_data() { test::addSolverMethodRows(); }
    void risesAtCappedStokesSpeed() {
        QFETCH(QString, method);
        const double target = 0.25; // 2/9 g R²/ν = 3490 m/s for R = 4 cm: the cap holds
        const double speed = riseSpeed(method.toStdString());
        QVERIFY2(std::abs(speed / target - 1.0) < 0.15,
                 qPrintable(QString("rise speed %1 m/s, target %2").arg(speed).arg(target)));
    }

    //! The auxiliary force (eq. 5) is applied per step: the rise must not depend on the step,
    //! which DFSPH takes ten to twenty times longer than WCSPH.
    void riseSpeedIsTheSameUnderBothSolvers() {
        const double wcsph = riseSpeed("wcsph");
        const double dfsph = riseSpeed("dfsph");
        qInfo("rise speed %.4f m/s with WCSPH, %.4f m/s with DFSPH (%+.2f %%)", wcsph, dfsph,
              100.0 * (dfsph / wcsph - 1.0));
        QVERIFY2(std::abs(dfsph / wcsph - 1.0) < 0.02,
                 qPrintable(QString("WCSPH %1 m/s, DFSPH %2 m/s").arg(wcsph).arg(dfsph)));
    }

    //! DFSPH's step is the flow's: a bubble rising at 0.25 m/s would hold it to 3.9 ms under the
    //! dynamic bodies' limit of 0.05 spacings per step, which bubbles are free of
    //! (docs/METHOD.md "Bodies and the step"); the still water allows max_time_step, 5 ms.
    void dfsphStepIsNotLimitedByTheBubble() {
        riseSpeed("dfsph");
        const double longest = tallStillTank().solver.maxTimeStep;
        qInfo("mean DFSPH step over 0.3–0.9 s: %.4f ms of at most %.4f ms", 1e3 * meanStep_,
              1e3 * longest);
        QVERIFY2(meanStep_ > 0.95 * longest,
                 qPrintable(QString("mean step %1 s, longest %2 s").arg(meanStep_).arg(longest)));
    }

private:
    //! The mean rise speed over 0.3–0.9 s of a bubble of radius 4 cm released at rest, baked
    //! once per method; for DFSPH also its mean step over that time (meanStep_).
    double riseSpeed(const std::string& method) {
        const auto found = speeds_.find(method);
        if (found != speeds_.end())
            return found->second;
        Scene scene = tallStillTank();
        scene.solver.method = method;
        scene.bubbles.maxRiseSpeed = 0.25;
        const double radius = 0.04;
        auto simulation =
            test::simulationWithBubbles(scene, {test::bubbleAt(0, Vec3d(0.2, 0.2, 0.2), radius)});
        double startHeight = 0.0;
        double startTime = 0.0;
        std::uint64_t startStep = 0;
        while (simulation->state().time < 0.9) {
            simulation->step(1.0);
            if (simulation->state().bubbles.size() != 1) {
                qWarning("%s: the bubble was deleted at %.3f s", method.c_str(),
                         simulation->state().time);
                return speeds_[method] = 0.0;
            }
            const double t = simulation->state().time;
            if (startTime == 0.0 && t >= 0.3) {
                startTime = t;
                startHeight = simulation->state().bubbles[0].body.position.y();
                startStep = simulation->state().steps;
            }
        }
        if (method == "dfsph")
            meanStep_ = (simulation->state().time - startTime) /
                        double(simulation->state().steps - startStep);
        const BubbleState& bubble = simulation->state().bubbles[0];
        const double speed =
            (bubble.body.position.y() - startHeight) / (simulation->state().time - startTime);
        qInfo("%s: mean rise speed over 0.3–0.9 s %.4f m/s, now at y = %.3f, drift %.4f m",
              method.c_str(), speed, bubble.body.position.y(),
              (bubble.body.position - Vec3d(0.2, bubble.body.position.y(), 0.2)).norm());
        return speeds_[method] = speed;
    }

    std::map<std::string, double> speeds_;
    double meanStep_ = 0.0; //!< s
};

AIRTRAP_TEST_APPLESS(TestBubbleRise)
#include "TestBubbleRise.moc"
