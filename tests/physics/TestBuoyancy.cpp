// Paper Fig. 1: a cube of density ratio 10, a sphere of 1 and a cylinder of 0.1 released at rest
// in a pool. Buoyancy comes only from the water's pressure on the boundary particles (eq. 4); the
// engine has no buoyancy term. After 2 s the cube rests on the floor, the sphere has stayed
// where it was (within a few particle spacings) and the cylinder floats with most of its height
// above the water. Runs samples/buoyancy.json as shipped with each pressure solver (about a
// minute each on 2 cores).
#include "scene/SceneJson.h"
#include "sim/SceneSetup.h"
#include "sim/Simulation.h"
#include "support/SolverMethods.h"
#include "support/TestMain.h"

#include <QtTest>
#include <map>

using namespace airtrap;

class TestBuoyancy : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        scene_ = readSceneFile(AIRTRAP_SOURCE_DIR "/samples/buoyancy.json");
        QCOMPARE(scene_.bodies.size(), std::size_t(3));
        QCOMPARE(scene_.frameTime(scene_.frames.endFrame), 2.0);
    }

    //! Density ratio 10: on the floor, at rest, upright (the floor is y = 0).
    void heavyCubeRestsOnTheFloor_data() { test::addSolverMethodRows(); }
    void heavyCubeRestsOnTheFloor() {
        const RigidBodyState& cube = bake().end[0];
        const double halfEdge = 0.5 * scene_.bodies[0].size.y();
        QVERIFY2(std::abs(cube.position.y() - halfEdge) < 0.1 * spacing(),
                 qPrintable(QString("cube centre at y = %1 m, resting would be %2 m")
                                .arg(cube.position.y())
                                .arg(halfEdge)));
        QVERIFY2(cube.linearVelocity.norm() < 0.01, "the cube is still moving");
        // Upright: its up axis is the world's. A turn about the vertical leaves it as flat on the
        // floor, so it is reported but not held against it.
        const Vec3d up = cube.orientation * Vec3d::UnitY();
        const double tilt = std::acos(std::clamp(up.y(), -1.0, 1.0));
        qInfo("the cube tilted %.4f rad and turned %.4f rad in all", tilt,
              cube.orientation.angularDistance(Quatd::Identity()));
        QVERIFY2(tilt < 0.05, qPrintable(QString("the cube tilted %1 rad").arg(tilt)));
    }

    //! Density ratio 1: hovers where it was released, to within a few spacings.
    void neutralSphereStaysPut_data() { test::addSolverMethodRows(); }
    void neutralSphereStaysPut() {
        const Outcome& outcome = bake();
        const double drift = (outcome.end[1].position - outcome.start[1].position).norm();
        QVERIFY2(drift < 3.0 * spacing(),
                 qPrintable(QString("the sphere drifted %1 m = %2 spacings")
                                .arg(drift)
                                .arg(drift / spacing())));
        QVERIFY2(outcome.end[1].linearVelocity.norm() < 0.05, "the sphere is still moving off");
    }

    //! Density ratio 0.1: at the surface, its centre above the water and its lowest point below
    //! it. The water level is the pool's top plus what the three bodies displace in it. A
    //! cylinder 1.2 diameters tall floating this light is unstable upright and may lie down, so
    //! its lowest point comes from its orientation.
    void lightCylinderFloats_data() { test::addSolverMethodRows(); }
    void lightCylinderFloats() {
        const double surface = waterLevel();
        const RigidBodyState& cylinder = bake().end[2];
        const RigidBodySettings& shape = scene_.bodies[2];
        const double axisUp = std::abs((cylinder.orientation * Vec3d::UnitY()).y());
        const double halfExtent =
            axisUp * 0.5 * shape.height + std::sqrt(1.0 - axisUp * axisUp) * shape.radius;
        QVERIFY2(cylinder.position.y() > surface,
                 qPrintable(QString("cylinder centre %1 m below the surface %2 m")
                                .arg(cylinder.position.y())
                                .arg(surface)));
        // Upright or lying, about a tenth of its height across would be under water; at this
        // resolution the draft is resolved to about a spacing.
        const double draft = surface - (cylinder.position.y() - halfExtent);
        qInfo("cylinder axis %.2f from vertical (cos), draft %.4f m of %.4f m across, water level "
              "%.4f m",
              axisUp, draft, 2.0 * halfExtent, surface);
        QVERIFY2(draft > 0.0 && draft < 0.15 * 2.0 * halfExtent + spacing(),
                 qPrintable(QString("draft %1 m").arg(draft)));
        QVERIFY2(cylinder.linearVelocity.norm() < 0.05, "the cylinder is still moving");
    }

private:
    struct Outcome {
        std::vector<RigidBodyState> start;
        std::vector<RigidBodyState> end;
    };

    //! The bake of the row's method, run once for all the checks of that row.
    const Outcome& bake() {
        QFETCH(QString, method);
        auto found = outcomes_.find(method);
        if (found != outcomes_.end())
            return found->second;
        Scene scene = scene_;
        scene.solver.method = method.toStdString();
        Simulation simulation(scene);
        Outcome outcome;
        outcome.start = simulation.state().bodies;
        Interrupter interrupter;
        while (simulation.frame() < scene.frames.endFrame)
            simulation.advanceFrame(interrupter);
        outcome.end = simulation.state().bodies;
        for (std::size_t k = 0; k < outcome.end.size(); ++k)
            qInfo("%s, %s: y %.4f -> %.4f m, speed %.4f m/s", qPrintable(method),
                  scene.bodies[k].name.c_str(), outcome.start[k].position.y(),
                  outcome.end[k].position.y(), outcome.end[k].linearVelocity.norm());
        return outcomes_.emplace(method, std::move(outcome)).first->second;
    }

    double spacing() const { return scene_.solver.particleSpacing; }

    double waterLevel() const {
        const FluidBlock& pool = scene_.fluidBlocks[0];
        const Vec3d extent = pool.max - pool.min;
        const double cube = scene_.bodies[0].size.prod();
        const double sphere = 4.0 / 3.0 * M_PI * std::pow(scene_.bodies[1].radius, 3);
        const RigidBodySettings& cylinder = scene_.bodies[2];
        const double floating = 0.1 * M_PI * cylinder.radius * cylinder.radius * cylinder.height;
        return pool.max.y() + (cube + sphere + floating) / (extent.x() * extent.z());
    }

    Scene scene_;
    std::map<QString, Outcome> outcomes_;
};

AIRTRAP_TEST_APPLESS(TestBuoyancy)
#include "TestBuoyancy.moc"
