// Dam break (docs/VALIDATION.md "Dam break"): a water column of width a and height 2a collapses
// along a dry floor. The surge front Z = z/a against time T = t·√(2g/a) is compared with the
// experiments of Martin & Moyce (1952) and Koshizuka & Oka (1996), as digitised in PySPH's
// db_exp_data.py (the figures used are copied below).
#include "sim/Simulation.h"
#include "support/TestMain.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <vector>

using namespace airtrap;

namespace {

struct Point {
    double T;
    double Z;
};

// Martin, J. C. & Moyce, W. J. (1952), Phil. Trans. R. Soc. A 244, 312–324, Fig. 3, n² = 2,
// digitised by PySPH (pysph/examples/db_exp_data.py, commit a57e6534): T ≤ 3 only.
const std::vector<Point> kMartinMoyceSmall = {
    {0.849, 1.245}, {1.212, 1.443}, {1.602, 1.884}, {2.283, 2.689}, {2.950, 3.728}}; // a = 1.125"
const std::vector<Point> kMartinMoyceLarge = {
    {0.832, 1.217}, {1.219, 1.474}, {1.997, 2.292}, {2.547, 2.995}}; // a = 2.25"
// Koshizuka, S. & Oka, Y. (1996), Nucl. Sci. Eng. 123, 421–434, experiment, same digitisation
// (the point past T = 3 only brackets the interpolation).
const std::vector<Point> kKoshizukaOka = {{0.381, 1.111}, {0.769, 1.252}, {1.153, 1.505},
                                          {1.537, 1.892}, {1.935, 2.241}, {2.323, 2.615},
                                          {2.719, 3.003}, {3.096, 3.624}};

constexpr double kWidth = 0.1;           // a, m
constexpr double kSpacing = kWidth / 25; // 25 particles across the column
constexpr double kGravity = 9.81;

Scene damBreak() {
    Scene scene;
    scene.name = "dam break test";
    scene.solver.particleSpacing = kSpacing;
    scene.solver.maxSpeed = 3.0; // above the front's 2√(g·a) ≈ 2 m/s
    // Frames every ΔT = 0.05.
    scene.frames.fps = std::sqrt(2.0 * kGravity / kWidth) / 0.05;
    scene.frames.endFrame = 1 + int(3.05 / 0.05);
    // A narrow flume, six particles deep: the flow is two-dimensional as in both experiments.
    const double depth = 6 * kSpacing;
    scene.container.max = Vec3d(6 * kWidth, 3 * kWidth, depth);
    scene.container.headroom = kWidth;
    FluidBlock column;
    column.max = Vec3d(kWidth, 2 * kWidth, depth);
    scene.fluidBlocks.push_back(column);
    return scene;
}

//! The leading edge: the largest x reached by water in the lower half of the column's height,
//! plus the half spacing each particle stands for.
double frontPosition(const ParticleSet& fluid) {
    float front = 0.0f;
    for (const Vec3f& x : fluid.positions)
        if (x.y() < 0.5 * kWidth)
            front = std::max(front, x.x());
    return (front + 0.5 * kSpacing) / kWidth;
}

//! Linear interpolation of the simulated Z at time T.
double interpolate(const std::vector<Point>& curve, double T) {
    const auto after = std::lower_bound(curve.begin(), curve.end(), T,
                                        [](const Point& p, double t) { return p.T < t; });
    if (after == curve.begin())
        return after->Z;
    if (after == curve.end())
        return curve.back().Z;
    const Point& b = *after;
    const Point& a = *(after - 1);
    return a.Z + (T - a.T) / (b.T - a.T) * (b.Z - a.Z);
}

double relativeError(const std::vector<Point>& simulated, const Point& measured) {
    return interpolate(simulated, measured.T) / measured.Z - 1.0;
}

class TestDamBreak : public QObject {
    Q_OBJECT

    std::vector<Point> simulated_;

private Q_SLOTS:
    void initTestCase() {
        Simulation simulation(damBreak());
        Interrupter interrupter;
        const double timeScale = std::sqrt(2.0 * kGravity / kWidth);
        simulated_.push_back({0.0, frontPosition(simulation.state().fluid)});
        while (simulation.frame() < simulation.scene().frames.endFrame) {
            simulation.advanceFrame(interrupter);
            simulated_.push_back(
                {simulation.state().time * timeScale, frontPosition(simulation.state().fluid)});
        }
        QVERIFY(std::abs(simulated_.front().Z - 1.0) < 1e-6); // the column starts at x = a
    }

    //! Within 10 % of Martin & Moyce for T ≤ 3. Before T = 1.5 their fronts trail Koshizuka &
    //! Oka's, measured on the same column shape, by up to 8 % (T ≈ 1.2: Z = 1.44–1.47 against
    //! 1.56); the column's release is slower in their experiment. There a point passes when the
    //! simulation is within 10 % of either experiment, and the test prints both errors.
    void frontFollowsMartinAndMoyce() {
        for (const auto* series : {&kMartinMoyceSmall, &kMartinMoyceLarge})
            for (const Point& p : *series) {
                const double error = relativeError(simulated_, p);
                const Point koshizukaOka{p.T, interpolate(kKoshizukaOka, p.T)};
                const double errorOtherExperiment = relativeError(simulated_, koshizukaOka);
                qInfo("Martin & Moyce T = %.3f: Z = %.3f, simulated %.3f (%+.1f %%; against "
                      "Koshizuka & Oka %+.1f %%)",
                      p.T, p.Z, interpolate(simulated_, p.T), 100.0 * error,
                      100.0 * errorOtherExperiment);
                const bool withinMartinMoyce = std::abs(error) <= 0.10;
                const bool withinExperimentalSpread =
                    p.T < 1.5 && std::abs(errorOtherExperiment) <= 0.10;
                QVERIFY2(withinMartinMoyce || withinExperimentalSpread,
                         qPrintable(QString("T = %1: Z = %2 simulated against %3 measured")
                                        .arg(p.T)
                                        .arg(interpolate(simulated_, p.T))
                                        .arg(p.Z)));
            }
    }

    //! Within 10 % of Koshizuka & Oka's experiment at every T ≤ 3.
    void frontFollowsKoshizukaAndOka() {
        for (const Point& p : kKoshizukaOka) {
            if (p.T > 3.0)
                continue;
            const double error = relativeError(simulated_, p);
            qInfo("Koshizuka & Oka T = %.3f: Z = %.3f, simulated %.3f (%+.1f %%)", p.T, p.Z,
                  interpolate(simulated_, p.T), 100.0 * error);
            QVERIFY2(std::abs(error) <= 0.10,
                     qPrintable(QString("T = %1: %2 %").arg(p.T).arg(100 * error)));
        }
    }
};

} // namespace

AIRTRAP_TEST_APPLESS(TestDamBreak)
#include "TestDamBreak.moc"
