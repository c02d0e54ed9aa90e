// A static box obstacle in the path of a collapsing column: the water flows around and over it
// and never enters it, and none is lost; with either pressure solver.
#include "sim/Simulation.h"
#include "support/SceneBuilder.h"
#include "support/SolverMethods.h"
#include "support/TestMain.h"

#include <QtTest>

using namespace airtrap;
using airtrap::test::SceneBuilder;

class TestObstacle : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void waterStaysOutOfTheObstacle_data() { test::addSolverMethodRows(); }
    void waterStaysOutOfTheObstacle() {
        QFETCH(QString, method);
        Scene scene = SceneBuilder()
                          .spacing(0.02)
                          .maxSpeed(4.0)
                          // 0.8 s: the surge reaches the box, climbs it, falls back
                          .frames(20.0, 1 + 16)
                          .tank({1.0, 1.4, 0.2}) // tall: the jet off the box climbs 1.1 m
                          .water({0.0, 0.0, 0.0}, {0.3, 0.4, 0.2})
                          .build();
        BoxObstacle box;
        box.center = Vec3d(0.6, 0.075, 0.1);
        box.size = Vec3d(0.1, 0.15, 0.2);
        scene.obstacles.push_back(box);
        scene.solver.method = method.toStdString();

        Simulation simulation(scene);
        const std::size_t count = simulation.state().fluid.size();
        Interrupter interrupter;
        // The box shrunk by a quarter spacing: particles rest half a spacing off its faces.
        const Aabb inside = Aabb{box.center - 0.5 * box.size, box.center + 0.5 * box.size}.expanded(
            -0.25 * scene.solver.particleSpacing);
        bool reachedTheBox = false;
        while (simulation.frame() < scene.frames.endFrame) {
            simulation.advanceFrame(interrupter);
            for (const Vec3f& x : simulation.state().fluid.positions) {
                QVERIFY2(!inside.contains(x.cast<double>()),
                         qPrintable(QString("frame %1: particle at (%2, %3, %4) inside the box")
                                        .arg(simulation.frame())
                                        .arg(x.x())
                                        .arg(x.y())
                                        .arg(x.z())));
                reachedTheBox = reachedTheBox || x.x() > 0.65f;
            }
        }
        QVERIFY2(reachedTheBox, "the surge never got past the box; the test proves nothing");
        QCOMPARE(simulation.state().fluid.size(), count);
    }
};

AIRTRAP_TEST_APPLESS(TestObstacle)
#include "TestObstacle.moc"
