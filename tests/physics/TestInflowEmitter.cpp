// The inflow emitter (pouring water): it keeps its budget and its time window, lays particles on
// the spacing lattice with layers one spacing apart, pours into a tank without exploding, and a
// resumed bake emits exactly what a straight one does.
#include "cache/FrameCache.h"
#include "scene/SceneJson.h"
#include "sim/InflowEmitter.h"
#include "sim/SceneCheck.h"
#include "sim/Simulation.h"
#include "support/SceneBuilder.h"
#include "support/SolverMethods.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <numbers>

using namespace airtrap;
using airtrap::test::SceneBuilder;

namespace {

constexpr double kEmitterSpacing = 0.01;

InflowEmitterSettings disc(double radius) {
    InflowEmitterSettings settings;
    settings.radius = radius;
    settings.position = Vec3d(0.5, 0.8, 0.5);
    settings.speed = 2.0;
    settings.startTime = 0.1;
    settings.stopTime = 0.3;
    return settings;
}

//! Emits over [from, to) in steps of `dt`, as the simulation does, into `state`.
std::size_t emitInSteps(const InflowEmitter& emitter, double from, double to, double dt,
                        SimulationState& state) {
    std::size_t added = 0;
    for (double t = from; t < to; t += dt)
        added += emitter.emit(t, std::min(t + dt, to), state);
    return added;
}

//! A small tank with a shallow pool and a disc nozzle pouring straight down into it.
Scene pouring(const std::string& method = "wcsph") {
    Scene scene = SceneBuilder()
                      .spacing(0.02)
                      .maxSpeed(4.0)
                      .frames(30.0, 13) // 0.4 s: the jet reaches the pool after about 0.16 s
                      .tank({0.3, 0.45, 0.3}, 0.1)
                      .water({0.0, 0.0, 0.0}, {0.3, 0.06, 0.3}, Vec3d::Zero(), "Pool")
                      .build();
    InflowEmitterSettings jet;
    jet.position = Vec3d(0.15, 0.35, 0.15);
    jet.radius = 0.04;
    jet.speed = 1.0;
    jet.startTime = 0.0;
    jet.stopTime = 1.0;
    jet.maxParticles = 10000;
    scene.emitters.push_back(jet);
    scene.solver.method = method;
    return scene;
}

SimulationState bakeTo(Simulation& simulation, int lastFrame) {
    Interrupter interrupter;
    while (simulation.frame() < lastFrame)
        simulation.advanceFrame(interrupter);
    return simulation.state();
}

} // namespace

class TestInflowEmitter : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void keepsItsBudgetAndTimeWindow() {
        InflowEmitterSettings settings = disc(0.03);
        const std::size_t perLayer =
            InflowEmitter(settings, kEmitterSpacing, 1000.0).particlesPerLayer();
        settings.maxParticles = int(3 * perLayer);
        const InflowEmitter emitter(settings, kEmitterSpacing, 1000.0);
        QCOMPARE(emitter.layerBudget(), std::size_t(3));

        SimulationState state;
        state.nextParticleId = 7;
        QCOMPARE(emitInSteps(emitter, 0.0, settings.startTime, 1e-3, state), std::size_t(0));
        emitInSteps(emitter, settings.startTime, 1.0, 1e-3, state);
        QCOMPARE(state.fluid.size(), std::size_t(settings.maxParticles));
        QCOMPARE(state.nextParticleId, std::uint32_t(7 + settings.maxParticles));
        for (std::size_t i = 0; i < state.fluid.size(); ++i)
            QCOMPARE(state.fluid.ids[i], std::uint32_t(7 + i));

        // A budget that ends inside a layer stops at the last whole layer.
        settings.maxParticles += int(perLayer) - 1;
        QCOMPARE(InflowEmitter(settings, kEmitterSpacing, 1000.0).layerBudget(), std::size_t(3));

        // With budget to spare, layers leave every Δx/speed from start until stop, not after.
        settings.maxParticles = 1000000;
        const InflowEmitter unlimited(settings, kEmitterSpacing, 1000.0);
        SimulationState all;
        emitInSteps(unlimited, 0.0, 2.0, 7e-4, all);
        const auto layers = std::size_t(std::ceil(
            (settings.stopTime - settings.startTime) * settings.speed / kEmitterSpacing - 1e-9));
        QCOMPARE(all.fluid.size(), layers * perLayer);
        QCOMPARE(unlimited.emit(settings.stopTime, 5.0, all), std::size_t(0));
        QCOMPARE(unlimited.layersBefore(settings.startTime), std::size_t(0));
    }

    void emitsEvenlySpacedLayers() {
        InflowEmitterSettings settings = disc(0.05);
        settings.direction = Vec3d(1.0, -2.0, 0.5); // oblique: the nozzle frame must be square
        const InflowEmitter emitter(settings, kEmitterSpacing, 1000.0);
        const double area = std::numbers::pi * settings.radius * settings.radius;
        const double expected = area / (kEmitterSpacing * kEmitterSpacing);
        QVERIFY2(std::abs(double(emitter.particlesPerLayer()) / expected - 1.0) < 0.1,
                 qPrintable(QString("%1 particles per layer, expected about %2")
                                .arg(emitter.particlesPerLayer())
                                .arg(expected)));

        // One emission over several layers' time: the layers are where the jet has taken them.
        SimulationState state;
        emitter.emit(0.0, settings.startTime + 4.5 * kEmitterSpacing / settings.speed, state);
        const ParticleSet& fluid = state.fluid;
        QCOMPARE(fluid.size(), 5 * emitter.particlesPerLayer());
        const Vec3d d = emitter.direction();
        for (std::size_t i = 0; i < fluid.size(); ++i) {
            double nearest = 1e9;
            for (std::size_t j = 0; j < fluid.size(); ++j)
                if (j != i)
                    nearest =
                        std::min(nearest, double((fluid.positions[i] - fluid.positions[j]).norm()));
            QVERIFY2(
                std::abs(nearest / kEmitterSpacing - 1.0) < 0.01,
                qPrintable(QString("particle %1: nearest neighbour at %2 m").arg(i).arg(nearest)));
            // Layer k sits (4.5 − k)·Δx beyond the nozzle plane, every particle moving at speed.
            const std::size_t layer = i / emitter.particlesPerLayer();
            const double along = (fluid.positions[i].cast<double>() - settings.position).dot(d);
            QVERIFY(std::abs(along - (4.5 - double(layer)) * kEmitterSpacing) <
                    1e-3 * kEmitterSpacing);
            QVERIFY((fluid.velocities[i].cast<double>() - settings.speed * d).norm() < 1e-5);
            QCOMPARE(fluid.densities[i], 1000.0f);
        }
    }

    void rectangleSpansWidthAndHeight() {
        InflowEmitterSettings settings;
        settings.shape = "rectangle";
        settings.direction = Vec3d(1.0, 0.0, 0.0);
        settings.width = 0.08;
        settings.height = 0.05;
        const InflowEmitter emitter(settings, kEmitterSpacing, 1000.0);
        QCOMPARE(emitter.particlesPerLayer(), std::size_t(8 * 5));
        // A horizontal jet along x: the width is horizontal (z), the height vertical (y).
        QVERIFY(std::abs(emitter.widthAxis().z()) > 0.999);
        QVERIFY(std::abs(emitter.heightAxis().y()) > 0.999);
    }

    void validatorNamesTheEmitter() {
        Scene scene = pouring();
        QVERIFY(SceneCheck::run(scene).ok());
        scene.emitters[0].speed = 5.0;
        scene.emitters[0].stopTime = -0.0;
        scene.emitters[0].position.x() = 0.29;
        const SceneIssues issues = SceneCheck::run(scene);
        // The speed, the time window, the position, and (WCSPH) a jet faster than max_speed.
        QCOMPARE(issues.errors.size(), std::size_t(4));
        for (const std::string& message : issues.errors)
            QVERIFY2(message.find("emitters[0]") != std::string::npos, message.c_str());
        scene = pouring();
        scene.emitters[0].direction = Vec3d::Zero();
        QCOMPARE(SceneCheck::run(scene).errors.size(), std::size_t(1));
        // The emitter survives the scene file.
        const Scene reread = sceneFromJson(sceneToJson(pouring()), "test");
        QCOMPARE(reread.emitters.size(), std::size_t(1));
        QCOMPARE(reread.emitters[0].radius, 0.04);
        QCOMPARE(reread.emitters[0].shape, std::string("disc"));
    }

    void anEmitterAloneIsEnoughWater() {
        Scene scene = pouring();
        scene.fluidBlocks.clear();
        scene.frames.endFrame = 4;
        QVERIFY(SceneCheck::run(scene).ok());
        Simulation simulation(scene);
        QCOMPARE(simulation.state().fluid.size(), std::size_t(0));
        Interrupter interrupter;
        while (simulation.frame() < scene.frames.endFrame)
            simulation.advanceFrame(interrupter);
        const InflowEmitter emitter(scene.emitters[0], scene.solver.particleSpacing,
                                    scene.solver.restDensity);
        const std::size_t expected =
            emitter.layersBefore(simulation.state().time) * emitter.particlesPerLayer();
        QVERIFY(expected > 0);
        QCOMPARE(simulation.state().fluid.size(), expected);

        scene.emitters.clear();
        const SceneIssues issues = SceneCheck::run(scene);
        QCOMPARE(issues.errors.size(), std::size_t(1));
        QVERIFY2(issues.errors[0].find("at least one fluid block or emitter") != std::string::npos,
                 issues.errors[0].c_str());
    }

    void poursIntoATankWithoutExploding_data() { test::addSolverMethodRows(); }
    void poursIntoATankWithoutExploding() {
        QFETCH(QString, method);
        const Scene scene = pouring(method.toStdString());
        // WCSPH's densities come from the continuity equation and stay near ρ₀ everywhere; DFSPH
        // sums them, and a jet's particles, with few neighbours, sum to far less without any
        // fault: there only compression is an error, as the engine's own guard counts it.
        const bool summed = scene.solver.method == "dfsph";
        const InflowEmitterSettings& jet = scene.emitters[0];
        const InflowEmitter emitter(jet, scene.solver.particleSpacing, scene.solver.restDensity);
        Simulation simulation(scene);
        const std::size_t pool = simulation.state().fluid.size();
        const double fall = jet.position.y() - 0.06;
        const double speedBound = 2.0 * jet.speed + std::sqrt(2.0 * 9.81 * fall);
        Interrupter interrupter;
        std::size_t previous = pool;
        while (simulation.frame() < scene.frames.endFrame) {
            simulation.advanceFrame(interrupter);
            const SimulationState& state = simulation.state();
            const ParticleSet& fluid = state.fluid;
            const std::size_t emitted =
                emitter.layersBefore(state.time) * emitter.particlesPerLayer();
            QCOMPARE(fluid.size(), pool + emitted);
            QVERIFY(fluid.size() > previous);
            previous = fluid.size();
            double maxError = 0.0;
            for (std::size_t i = 0; i < fluid.size(); ++i) {
                QVERIFY(fluid.positions[i].allFinite() && fluid.velocities[i].allFinite());
                const double deviation = fluid.densities[i] / 1000.0 - 1.0;
                maxError = std::max(maxError, summed ? deviation : std::abs(deviation));
            }
            QVERIFY2(
                maxError < scene.solver.maxDensityError,
                qPrintable(QString("frame %1: density error %2").arg(state.frame).arg(maxError)));
            QVERIFY2(simulation.lastFrameStats().maxSpeed < speedBound,
                     qPrintable(QString("frame %1: %2 m/s")
                                    .arg(state.frame)
                                    .arg(simulation.lastFrameStats().maxSpeed)));
        }
        // The jet reached the pool: some emitted water is down at the pool's surface.
        bool reached = false;
        for (std::size_t i = 0; i < simulation.state().fluid.size(); ++i)
            reached = reached || (simulation.state().fluid.ids[i] >= pool &&
                                  simulation.state().fluid.positions[i].y() < 0.1f);
        QVERIFY2(reached, "the jet never reached the pool; the test proves nothing");
    }

    void resumeIsBitIdentical_data() { test::addSolverMethodRows(); }
    void resumeIsBitIdentical() {
        QFETCH(QString, method);
        Scene scene = pouring(method.toStdString());
        scene.frames.endFrame = 5;
        Simulation straight(scene);
        const SimulationState uninterrupted = bakeTo(straight, 5);

        QTemporaryDir dir;
        const std::string path = dir.filePath("cache").toStdString();
        {
            FrameCache cache = FrameCache::create(path, sceneToJson(scene), parameterHash(scene),
                                                  scene.frames.fps);
            Simulation first(scene);
            bakeTo(first, 3);
            cache.writeFrame(first.state(), first.lastFrameStats());
        }
        const FrameCache reopened = FrameCache::open(path);
        Simulation resumed(scene, reopened.readFrame(3).state);
        const SimulationState continued = bakeTo(resumed, 5);
        QVERIFY(continued.fluid.size() > reopened.readFrame(3).state.fluid.size());
        QCOMPARE(continued.fluid.size(), uninterrupted.fluid.size());
        QVERIFY(continued == uninterrupted);
    }
};

AIRTRAP_TEST_APPLESS(TestInflowEmitter)
#include "TestInflowEmitter.moc"
