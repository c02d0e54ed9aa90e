// Two-way coupling conserves momentum (paper eq. 4, docs/METHOD.md "Impulse-based boundary force"):
// the water receives exactly what a body loses. A dense sphere is thrown into a block of water with
// gravity off, far from the container's walls, so nothing else exchanges momentum with either: over
// the impact the sphere's momentum loss and the water's gain agree within a few per cent.
#include "sim/Simulation.h"
#include "support/SceneBuilder.h"
#include "support/SolverMethods.h"
#include "support/TestMain.h"

#include <QtTest>

using namespace airtrap;
using airtrap::test::SceneBuilder;

namespace {

Vec3d waterMomentum(const ParticleSet& fluid, double particleMass) {
    Vec3d sum = Vec3d::Zero();
    for (const Vec3f& v : fluid.velocities)
        sum += v.cast<double>();
    return particleMass * sum;
}

} // namespace

class TestMomentumExchange : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void sphereLosesWhatTheWaterGains_data() { test::addSolverMethodRows(); }
    void sphereLosesWhatTheWaterGains() {
        QFETCH(QString, method);
        SceneBuilder builder;
        builder.spacing(0.02)
            .maxSpeed(4.0)
            .tank({1.4, 1.0, 1.0})
            .water({0.5, 0.3, 0.3}, {0.9, 0.7, 0.7});
        builder.scene().solver.gravity = Vec3d::Zero();
        builder.scene().solver.method = method.toStdString();
        RigidBodySettings sphere;
        sphere.name = "Sphere";
        sphere.shape = "sphere";
        sphere.radius = 0.06;
        sphere.density = 3000.0;
        sphere.position = Vec3d(0.3, 0.5, 0.5);
        sphere.linearVelocity = Vec3d(2.0, 0.0, 0.0);
        const Scene scene = builder.body(sphere).build();

        Simulation simulation(scene);
        const double particleMass = simulation.solver().particleMass();
        const double sphereMass = simulation.bodies().bodies().back().inertia().mass();
        const Vec3d water0 = waterMomentum(simulation.state().fluid, particleMass);
        const Vec3d sphere0 = sphereMass * simulation.state().bodies[0].linearVelocity;
        QVERIFY(water0.norm() < 1e-9);

        // The sphere reaches the block at t ≈ 0.07 s and is well inside it by 0.3 s.
        while (simulation.state().time < 0.3)
            simulation.step(1.0);

        const Vec3d sphereLoss = sphere0 - sphereMass * simulation.state().bodies[0].linearVelocity;
        const Vec3d waterGain = waterMomentum(simulation.state().fluid, particleMass) - water0;
        qInfo("sphere lost (%.5f, %.5f, %.5f) kg m/s, water gained (%.5f, %.5f, %.5f)",
              sphereLoss.x(), sphereLoss.y(), sphereLoss.z(), waterGain.x(), waterGain.y(),
              waterGain.z());
        // The impact must be real for the comparison to mean anything.
        QVERIFY2(sphereLoss.x() > 0.3 * sphere0.x(), "the sphere hardly slowed down");
        const double mismatch = (sphereLoss - waterGain).norm() / sphereLoss.norm();
        QVERIFY2(mismatch < 0.03,
                 qPrintable(QString("momentum mismatch %1 %").arg(100 * mismatch)));
        // No particle may have reached a wall: its force would break the balance unseen.
        const Aabb walls =
            Aabb{scene.container.min, scene.container.max}.expanded(-2.0 * scene.supportRadius());
        for (const Vec3f& x : simulation.state().fluid.positions)
            QVERIFY2(walls.contains(x.cast<double>()), "water reached a wall; enlarge the tank");
    }
};

AIRTRAP_TEST_APPLESS(TestMomentumExchange)
#include "TestMomentumExchange.moc"
