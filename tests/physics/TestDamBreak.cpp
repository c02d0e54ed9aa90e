// Dam break (docs/VALIDATION.md "Dam break"): a water column of width a and height 2a collapses
// along a dry floor. The surge front Z = z/a against time T = t·√(2g/a) is compared with the
// experiments of Martin & Moyce (1952) and Koshizuka & Oka (1996), as digitised in PySPH's
// db_exp_data.py (tests/data/dambreak_*.csv, read by readSeries()).
#include "sim/Simulation.h"
#include "support/SceneBuilder.h"
#include "support/SolverMethods.h"
#include "support/TestMain.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace airtrap;
using airtrap::test::SceneBuilder;

namespace {

struct Point {
    double T;
    double Z;
};

//! The points of `series` in the data file `name` (tests/data, dambreak.README.txt) with
//! 0 < T ≤ maxT, in file order. Columns: series, a second column, T, Z; # starts a comment.
std::vector<Point> readSeries(const std::string& name, const std::string& series, double maxT) {
    std::ifstream in(std::string(AIRTRAP_SOURCE_DIR "/tests/data/") + name);
    if (!in)
        throw std::runtime_error("cannot read tests/data/" + name);
    std::vector<Point> points;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line.front() == '#')
            continue;
        std::stringstream fields(line);
        std::string label, second, t, z;
        std::getline(fields, label, ',');
        std::getline(fields, second, ',');
        std::getline(fields, t, ',');
        std::getline(fields, z, ',');
        if (label != series)
            continue;
        const Point p{std::stod(t), std::stod(z)};
        if (p.T > 0.0 && p.T <= maxT)
            points.push_back(p);
    }
    return points;
}

// Martin & Moyce (1952), Fig. 3, n² = 2, T ≤ 3 only; Koshizuka & Oka (1996), the experiment, with
// the first point past T = 3, which only brackets the interpolation.
const std::vector<Point> kMartinMoyceSmall =
    readSeries("dambreak_martin_moyce_1952.csv", "mm_data_1", 3.0); // a = 1.125"
const std::vector<Point> kMartinMoyceLarge =
    readSeries("dambreak_martin_moyce_1952.csv", "mm_data_2", 3.0); // a = 2.25"
const std::vector<Point> kKoshizukaOka =
    readSeries("dambreak_koshizuka_oka_1996.csv", "ko_data", 3.1);

constexpr double kWidth = 0.1;           // a, m
constexpr double kSpacing = kWidth / 25; // 25 particles across the column
constexpr double kGravity = 9.81;

Scene damBreak(const std::string& method) {
    // A narrow flume, six particles deep: the flow is two-dimensional as in both experiments.
    const double depth = 6 * kSpacing;
    Scene scene = SceneBuilder()
                      .spacing(kSpacing)
                      .maxSpeed(3.0) // above the front's 2√(g·a) ≈ 2 m/s
                      // Frames every ΔT = 0.05.
                      .frames(std::sqrt(2.0 * kGravity / kWidth) / 0.05, 1 + int(3.05 / 0.05))
                      .tank({6 * kWidth, 3 * kWidth, depth}, kWidth)
                      .water({0.0, 0.0, 0.0}, {kWidth, 2 * kWidth, depth})
                      .build();
    scene.name = "dam break test";
    scene.solver.method = method;
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

//! The front's course and the solves' figures of one bake.
struct Bake {
    std::vector<Point> front;
    std::vector<PressureSolveStats> solves; //!< per frame (DFSPH)
};

Bake bakeDamBreak(const std::string& method) {
    Simulation simulation(damBreak(method));
    Interrupter interrupter;
    const double timeScale = std::sqrt(2.0 * kGravity / kWidth);
    Bake bake;
    bake.front.push_back({0.0, frontPosition(simulation.state().fluid)});
    while (simulation.frame() < simulation.scene().frames.endFrame) {
        simulation.advanceFrame(interrupter);
        bake.front.push_back(
            {simulation.state().time * timeScale, frontPosition(simulation.state().fluid)});
        bake.solves.push_back(simulation.lastFrameStats().pressureSolve);
    }
    return bake;
}

class TestDamBreak : public QObject {
    Q_OBJECT

    std::map<QString, Bake> bakes_;

    //! The bake of the current row's method, made on first use.
    const Bake& bake() {
        QFETCH(QString, method);
        auto found = bakes_.find(method);
        if (found == bakes_.end())
            found = bakes_.emplace(method, bakeDamBreak(method.toStdString())).first;
        return found->second;
    }

private Q_SLOTS:
    void initTestCase() {
        // The experiments as the data files hold them: 5 and 4 points to T = 3, 8 to 3.1.
        QCOMPARE(kMartinMoyceSmall.size(), std::size_t(5));
        QCOMPARE(kMartinMoyceLarge.size(), std::size_t(4));
        QCOMPARE(kKoshizukaOka.size(), std::size_t(8));
        QVERIFY(std::abs(frontPosition(Simulation(damBreak("wcsph")).state().fluid) - 1.0) <
                1e-6); // the column starts at x = a
    }

    //! Within 10 % of Martin & Moyce for T ≤ 3. Before T = 1.5 their fronts trail Koshizuka &
    //! Oka's, measured on the same column shape, by up to 8 % (T ≈ 1.2: Z = 1.44–1.47 against
    //! 1.56); the column's release is slower in their experiment. There a point passes when the
    //! simulation is within 10 % of either experiment, and the test prints both errors.
    void frontFollowsMartinAndMoyce_data() { test::addSolverMethodRows(); }
    void frontFollowsMartinAndMoyce() {
        const std::vector<Point>& simulated = bake().front;
        for (const auto* series : {&kMartinMoyceSmall, &kMartinMoyceLarge})
            for (const Point& p : *series) {
                const double error = relativeError(simulated, p);
                const Point koshizukaOka{p.T, interpolate(kKoshizukaOka, p.T)};
                const double errorOtherExperiment = relativeError(simulated, koshizukaOka);
                qInfo("Martin & Moyce T = %.3f: Z = %.3f, simulated %.3f (%+.1f %%; against "
                      "Koshizuka & Oka %+.1f %%)",
                      p.T, p.Z, interpolate(simulated, p.T), 100.0 * error,
                      100.0 * errorOtherExperiment);
                const bool withinMartinMoyce = std::abs(error) <= 0.10;
                const bool withinExperimentalSpread =
                    p.T < 1.5 && std::abs(errorOtherExperiment) <= 0.10;
                QVERIFY2(withinMartinMoyce || withinExperimentalSpread,
                         qPrintable(QString("T = %1: Z = %2 simulated against %3 measured")
                                        .arg(p.T)
                                        .arg(interpolate(simulated, p.T))
                                        .arg(p.Z)));
            }
    }

    //! Within 10 % of Koshizuka & Oka's experiment at every T ≤ 3.
    void frontFollowsKoshizukaAndOka_data() { test::addSolverMethodRows(); }
    void frontFollowsKoshizukaAndOka() {
        const std::vector<Point>& simulated = bake().front;
        for (const Point& p : kKoshizukaOka) {
            if (p.T > 3.0)
                continue;
            const double error = relativeError(simulated, p);
            qInfo("Koshizuka & Oka T = %.3f: Z = %.3f, simulated %.3f (%+.1f %%)", p.T, p.Z,
                  interpolate(simulated, p.T), 100.0 * error);
            QVERIFY2(std::abs(error) <= 0.10,
                     qPrintable(QString("T = %1: %2 %").arg(p.T).arg(100 * error)));
        }
    }

    //! DFSPH holds the water to its target compression: after the release (T > 0.5) every step
    //! ends with an average density error at most solver.density_error; during it, while the
    //! solve builds the column's pressure from nothing, a few steps stop at max_iterations
    //! within three times the target.
    void densityErrorStaysWithinTheTarget_data() {
        QTest::addColumn<QString>("method");
        QTest::newRow("dfsph") << "dfsph";
    }

    void densityErrorStaysWithinTheTarget() {
        const double target = SolverSettings{}.densityErrorTarget;
        const std::size_t releaseFrames = 10; // ΔT = 0.05 each
        std::uint64_t steps = 0, iterations = 0, unconvergedInRelease = 0;
        for (std::size_t k = 0; k < bake().solves.size(); ++k) {
            const PressureSolveStats& solve = bake().solves[k];
            const bool release = k < releaseFrames;
            const QString where = QString("frame %1: %2 %, %3 of %4 steps unconverged")
                                      .arg(k + 2)
                                      .arg(100.0 * solve.maxDensityError)
                                      .arg(solve.unconvergedSteps)
                                      .arg(solve.steps);
            QVERIFY2(solve.maxDensityError <= (release ? 3.0 : 1.0) * target, qPrintable(where));
            if (!release)
                QVERIFY2(solve.unconvergedSteps == 0, qPrintable(where));
            unconvergedInRelease += release ? solve.unconvergedSteps : 0;
            steps += solve.steps;
            iterations += solve.densityIterations;
        }
        qInfo("%llu steps, %.1f density iterations per step, %llu unconverged in the release",
              static_cast<unsigned long long>(steps), double(iterations) / double(steps),
              static_cast<unsigned long long>(unconvergedInRelease));
        QVERIFY(steps > 100);
        QVERIFY(unconvergedInRelease <= 5);
    }
};

} // namespace

AIRTRAP_TEST_APPLESS(TestDamBreak)
#include "TestDamBreak.moc"
