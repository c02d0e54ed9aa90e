// A resting tank: after settling, the pressure at depth d, averaged over the steps of the last
// 0.3 s, equals ρ₀ g d within 5 %, no particle leaves, the particle count stays constant and the
// water is at rest; with either pressure solver (WCSPH's pressure from the equation of state,
// DFSPH's from its density solve).
#include "core/Error.h"
#include "sim/Simulation.h"
#include "support/SceneBuilder.h"
#include "support/SolverMethods.h"
#include "support/TestMain.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <map>

using namespace airtrap;
using airtrap::test::SceneBuilder;

namespace {

//! Per layer below the surface: the sum of the pressures sampled and their count.
using LayerPressures = std::map<int, std::pair<double, int>>;
constexpr int kAveragedFrames = 3; // 0.3 s, a few periods of the column's slowest sloshing

constexpr double kTankSpacing = 0.02; // m
constexpr double kDepth = 0.4;        // m of water
constexpr double kSettleSeconds = 1.0;

Scene tank(const std::string& method) {
    constexpr double kFps = 10.0;
    Scene scene = SceneBuilder()
                      .spacing(kTankSpacing)
                      .maxSpeed(3.0) // c = 30 m/s: still 10× the speed of any wave in 0.4 m
                      .frames(kFps, 1 + int(kSettleSeconds * kFps))
                      .tank({0.4, 0.6, 0.4}, 0.2)
                      .water({0.0, 0.0, 0.0}, {0.4, kDepth, 0.4})
                      .build();
    scene.name = "hydrostatic test";
    scene.solver.method = method;
    return scene;
}

//! Adds the pressure of each particle away from the side walls, as the solver has it, to its
//! layer below the water's current surface.
void addLayerPressures(const Simulation& simulation, LayerPressures& layers) {
    const ParticleSet& fluid = simulation.state().fluid;
    float surface = 0.0f;
    for (const Vec3f& x : fluid.positions)
        surface = std::max(surface, x.y());
    surface += 0.5f * float(kTankSpacing);
    for (std::size_t i = 0; i < fluid.size(); ++i) {
        const Vec3f& x = fluid.positions[i];
        if (x.x() < 0.1f || x.x() > 0.3f || x.z() < 0.1f || x.z() > 0.3f)
            continue;
        const int layer = int(std::floor((surface - x.y()) / kTankSpacing));
        layers[layer].first += simulation.solver().pressure(fluid, i);
        layers[layer].second += 1;
    }
}

double rms(const std::vector<Vec3f>& velocities) {
    double sumSquares = 0.0;
    for (const Vec3f& v : velocities)
        sumSquares += v.squaredNorm();
    return std::sqrt(sumSquares / double(velocities.size()));
}

} // namespace

class TestHydrostatic : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void pressureGrowsWithDepthAsRhoGD_data() { test::addSolverMethodRows(); }

    void pressureGrowsWithDepthAsRhoGD() {
        QFETCH(QString, method);
        Simulation simulation(tank(method.toStdString()));
        const std::size_t count = simulation.state().fluid.size();
        QCOMPARE(count, std::size_t(20 * 20 * 20));
        Interrupter interrupter;
        const int endFrame = simulation.scene().frames.endFrame;
        while (simulation.frame() < endFrame - kAveragedFrames)
            QVERIFY(simulation.advanceFrame(interrupter) == Simulation::Advance::FrameDone);
        // The pressure of every step of the last frames, per layer: DFSPH's pressure is what one
        // step's solve needed, and a solve stopped at its tolerance leaves the whole column a
        // little over- or under-supported, made up over the next steps; over time it must carry
        // the column's weight exactly.
        LayerPressures layers;
        while (simulation.frame() < endFrame)
            QVERIFY(simulation.advanceFrame(interrupter, [&](double) {
                addLayerPressures(simulation, layers);
            }) == Simulation::Advance::FrameDone);

        const ParticleSet& fluid = simulation.state().fluid;
        QCOMPARE(fluid.size(), count);
        // At rest: the spurious currents a weakly compressible solver keeps stay small against
        // the velocity scale √(gH) ≈ 2 m/s of this tank.
        const double rmsSpeed = rms(fluid.velocities);
        const double maxSpeed = simulation.lastFrameStats().maxSpeed;
        qInfo("rms speed %.4f m/s, max speed %.4f m/s", rmsSpeed, maxSpeed);
        QVERIFY2(rmsSpeed < 0.02 && maxSpeed < 0.1, // 1 % and 5 % of √(gH)
                 qPrintable(QString("rms %1 m/s, max %2 m/s").arg(rmsSpeed).arg(maxSpeed)));
        for (const Vec3f& x : fluid.positions)
            QVERIFY(x.y() > -0.5 * kTankSpacing && x.x() > -0.5 * kTankSpacing &&
                    x.z() > -0.5 * kTankSpacing);

        const double rhoG = 1000.0 * 9.81;
        int checked = 0;
        for (const auto& [layer, sum] : layers) {
            const double depth = (layer + 0.5) * kTankSpacing;
            if (depth < 0.1 || depth > kDepth - kTankSpacing)
                continue; // the top layers sit in the kernel's truncated support
            const double measured = sum.first / sum.second;
            const double expected = rhoG * depth;
            qInfo("depth %.3f m: p = %.1f Pa, rho0 g d = %.1f Pa (%+.2f %%)", depth, measured,
                  expected, 100.0 * (measured / expected - 1.0));
            QVERIFY2(std::abs(measured - expected) < 0.05 * expected,
                     qPrintable(QString("depth %1 m: p = %2 Pa, ρ₀gd = %3 Pa")
                                    .arg(depth)
                                    .arg(measured)
                                    .arg(expected)));
            ++checked;
        }
        QVERIFY(checked >= 10);
    }

    //! A tank 45 layers deep stands still for half a second. DFSPH does not yet: the water over
    //! its floor compresses locally by 20–44 % while the average error stays within its 0.01 %,
    //! and the blow-up guard stops this bake at t = 0.05 s (docs/VALIDATION.md "A deep tank with
    //! DFSPH"). Recorded as an expected failure, so that this reports the day it holds.
    void aDeepTankStandsStill_data() { test::addSolverMethodRows(); }

    void aDeepTankStandsStill() {
        QFETCH(QString, method);
        constexpr double kDeepWater = 0.9; // m
        Scene scene = SceneBuilder()
                          .spacing(kTankSpacing)
                          .maxSpeed(1.5)
                          .frames(30.0, 16) // 0.5 s at the scenes' default rate
                          .tank({0.4, 1.0, 0.4}, 0.2)
                          .water({0.0, 0.0, 0.0}, {0.4, kDeepWater, 0.4})
                          .build();
        scene.solver.method = method.toStdString();
        Simulation simulation(scene);
        Interrupter interrupter;
        std::string stopped;
        double fastest = 0.0;
        try {
            while (simulation.frame() < scene.frames.endFrame) {
                simulation.advanceFrame(interrupter);
                fastest = std::max(fastest, simulation.lastFrameStats().maxSpeed);
            }
        } catch (const Error& error) {
            stopped = error.what();
        }
        QEXPECT_FAIL("dfsph", "the water over the floor compresses locally under a 0.9 m column",
                     Abort);
        QVERIFY2(stopped.empty(), stopped.c_str());
        const double rmsSpeed = rms(simulation.state().fluid.velocities);
        qInfo("after 0.5 s: rms speed %.4f m/s; fastest particle %.4f m/s", rmsSpeed, fastest);
        // Against √(gH) ≈ 3 m/s, the speed of a column that falls or is thrown up: 1.7 % and a
        // third of it.
        QVERIFY2(rmsSpeed < 0.05 && fastest < 1.0,
                 qPrintable(QString("rms %1 m/s, fastest %2 m/s").arg(rmsSpeed).arg(fastest)));
    }
};

AIRTRAP_TEST_APPLESS(TestHydrostatic)
#include "TestHydrostatic.moc"
