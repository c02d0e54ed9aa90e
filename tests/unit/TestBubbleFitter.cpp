// A bubble fitted to an air pocket (paper §3.4): at the cavity's centre, its size within 20 % of
// the cavity's, never touching the water, with its area fraction in water measured; a pocket too
// small for the minimum radius makes no bubble.
#include "bubbles/AirPocketFinder.h"
#include "bubbles/BubbleFitter.h"
#include "support/TestMain.h"

#include <QtTest>
#include <cmath>

using namespace airtrap;

namespace {

constexpr double kFitterSpacing = 0.02;
const Aabb kFitterDomain{Vec3d(0.0, 0.0, 0.0), Vec3d(0.8, 0.8, 0.8)};

struct Pool {
    NeighborGrid grid{kFitterDomain, 2.0f * float(kFitterSpacing)};
    PositionArrays sorted;
};

//! Lattice water up to y = 0.6 with a spherical cavity, sorted on its grid.
void fill(Pool& pool, const Vec3d& centre, double radius) {
    std::vector<Vec3f> points;
    for (int k = 0; k < 40; ++k)
        for (int j = 0; j < 30; ++j)
            for (int i = 0; i < 40; ++i) {
                const Vec3d x = (Vec3d(i, j, k) + Vec3d::Constant(0.5)) * kFitterSpacing;
                if ((x - centre).norm() >= radius)
                    points.push_back(x.cast<float>());
            }
    pool.grid.build(points);
    pool.sorted.gather(points, pool.grid.order());
}

double nearestDistance(const Pool& pool, const Vec3d& x) {
    double best = 1e9;
    for (std::size_t p = 0; p < pool.sorted.x.size(); ++p)
        best = std::min(best, (pool.sorted[p].cast<double>() - x).norm());
    return best;
}

} // namespace

class TestBubbleFitter : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void bubbleFitsItsCavity() {
        const Vec3d centre(0.41, 0.3, 0.39);
        const double radius = 0.1;
        Pool pool;
        fill(pool, centre, radius);
        AirPocketFinder finder;
        const auto pockets = finder.find(pool.grid, [](const Vec3d&) { return false; });
        QCOMPARE(pockets.size(), std::size_t(1));
        const BubbleFitter fitter(kFitterSpacing, 0.02);
        const std::optional<FittedBubble> bubble = fitter.fit(pockets[0], pool.grid, pool.sorted);
        QVERIFY(bubble.has_value());
        const double gapFraction =
            fitter.areaFractionInWater(bubble->centre, bubble->radius, pool.grid, pool.sorted);
        qInfo("bubble radius %.4f m in a %.2f m cavity, area fraction in water %.2f",
              bubble->radius, radius, gapFraction);
        QVERIFY((bubble->centre - centre).norm() < 2.0 * kFitterSpacing);
        QVERIFY(std::abs(bubble->radius - radius) < 0.2 * radius);
        // Its surface keeps half a spacing from every particle.
        QVERIFY(nearestDistance(pool, bubble->centre) >=
                bubble->radius + 0.5 * kFitterSpacing - 1e-6);
        QCOMPARE(bubble->pocketVolume, pockets[0].volume);

        // The pocket's whole cells fall short of the cavity, so this bubble floats in a gap of
        // about a spacing: little of its surface touches water. A pocket as large as the cavity
        // gives a bubble flush with the water, most of its surface wet. The sub-grid stage
        // fills the gap of the first with small bubbles (paper §4.2).
        AirPocket snug = pockets[0];
        snug.volume = 4.0 / 3.0 * M_PI * std::pow(radius - 0.5 * kFitterSpacing, 3);
        const std::optional<FittedBubble> flush = fitter.fit(snug, pool.grid, pool.sorted);
        QVERIFY(flush.has_value());
        const double flushFraction =
            fitter.areaFractionInWater(flush->centre, flush->radius, pool.grid, pool.sorted);
        qInfo("flush bubble radius %.4f m, area fraction in water %.2f", flush->radius,
              flushFraction);
        QVERIFY(flushFraction > 0.7); // the lattice leaves a few dry spots
        QVERIFY(gapFraction < 0.5);
    }

    void tooSmallAPocketMakesNoBubble() {
        Pool pool;
        fill(pool, Vec3d(0.41, 0.3, 0.39), 0.1);
        AirPocketFinder finder;
        const auto pockets = finder.find(pool.grid, [](const Vec3d&) { return false; });
        const BubbleFitter fitter(kFitterSpacing, 0.09);
        QVERIFY(!fitter.fit(pockets.at(0), pool.grid, pool.sorted).has_value());
    }
};

AIRTRAP_TEST_APPLESS(TestBubbleFitter)
#include "TestBubbleFitter.moc"
