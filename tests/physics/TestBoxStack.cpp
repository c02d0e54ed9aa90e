// Rigid–rigid contacts (docs/METHOD.md "Contacts between bodies"): three boxes dropped onto each
// other on the container's floor come to rest as a stack — no bounce, no sinking into each other,
// no tipping — through the same impulses as the water's contacts. A little water sits in a far
// corner because a scene needs some.
#include "sim/Simulation.h"
#include "support/SceneBuilder.h"
#include "support/SolverMethods.h"
#include "support/TestMain.h"

#include <QtTest>

using namespace airtrap;
using airtrap::test::SceneBuilder;

class TestBoxStack : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void threeBoxesComeToRest_data() { test::addSolverMethodRows(); }
    void threeBoxesComeToRest() {
        QFETCH(QString, method);
        SceneBuilder builder;
        builder.spacing(0.02)
            .maxSpeed(2.0)
            .frames(20.0, 1 + 30) // 1.5 s
            .tank({0.6, 0.6, 0.6})
            .water({0.0, 0.0, 0.0}, {0.06, 0.04, 0.06});
        constexpr double kEdge = 0.1;
        for (int k = 0; k < 3; ++k) {
            RigidBodySettings box;
            box.name = "Box " + std::to_string(k + 1);
            box.size = Vec3d::Constant(kEdge);
            box.density = 600.0;
            // Each starts 1 cm above where it will rest, so each lands on the one below.
            box.position = Vec3d(0.35, (k + 0.5) * kEdge + 0.01 * (k + 1), 0.35);
            builder.body(box);
        }
        Scene scene = builder.build();
        scene.solver.method = method.toStdString();

        Simulation simulation(scene);
        Interrupter interrupter;
        while (simulation.frame() < scene.frames.endFrame)
            simulation.advanceFrame(interrupter);

        const double spacing = scene.solver.particleSpacing;
        for (int k = 0; k < 3; ++k) {
            const RigidBodyState& box = simulation.state().bodies[k];
            const double resting = (k + 0.5) * kEdge;
            // Turning about the vertical does not matter to a stack; leaning does.
            const double tilt = std::acos(std::min(1.0, (box.orientation * Vec3d::UnitY()).y()));
            qInfo("box %d: y %.5f m (resting %.3f), speed %.5f m/s, tilt %.5f rad", k + 1,
                  box.position.y(), resting, box.linearVelocity.norm(), tilt);
            QVERIFY2(std::abs(box.position.y() - resting) < 0.1 * spacing,
                     qPrintable(QString("box %1 at y = %2 m").arg(k + 1).arg(box.position.y())));
            QVERIFY2(std::abs(box.position.x() - 0.35) < 0.1 * spacing, "the stack slid");
            QVERIFY2(box.linearVelocity.norm() < 0.005, "a box is still moving");
            QVERIFY2(box.angularVelocity.norm() < 0.05, "a box is still turning");
            QVERIFY2(tilt < 0.01, "a box leans");
        }
    }
};

AIRTRAP_TEST_APPLESS(TestBoxStack)
#include "TestBoxStack.moc"
