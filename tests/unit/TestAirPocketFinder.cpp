// Air pockets on the neighbour grid (paper §3.4): a closed cavity in the water is one pocket of
// the right place and size; a cavity open to the air (upwards or sideways), or one inside a
// solid, is none.
#include "bubbles/AirPocketFinder.h"
#include "support/TestMain.h"

#include <QtTest>
#include <cmath>

using namespace airtrap;

namespace {

constexpr double kSpacing = 0.02;
constexpr float kCell = 0.04f; // support radius = 2 spacings
const Aabb kDomain{Vec3d(0.0, 0.0, 0.0), Vec3d(0.8, 0.8, 0.8)};

//! Water on the particle lattice up to `surface`, leaving out the points `isHole` accepts.
template <class Hole>
std::vector<Vec3f> poolWithHole(double surface, Hole isHole) {
    std::vector<Vec3f> points;
    const int across = static_cast<int>(kDomain.size().x() / kSpacing);
    const int up = static_cast<int>(surface / kSpacing);
    for (int k = 0; k < across; ++k)
        for (int j = 0; j < up; ++j)
            for (int i = 0; i < across; ++i) {
                const Vec3d x = (Vec3d(i, j, k) + Vec3d::Constant(0.5)) * kSpacing;
                if (!isHole(x))
                    points.push_back(x.cast<float>());
            }
    return points;
}

const AirPocketFinder::SolidTest kNoSolids = [](const Vec3d&) { return false; };

} // namespace

class TestAirPocketFinder : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void closedCavityIsOnePocket() {
        const Vec3d centre(0.41, 0.3, 0.39);
        const double radius = 0.1;
        NeighborGrid grid(kDomain, kCell);
        grid.build(poolWithHole(0.6, [&](const Vec3d& x) { return (x - centre).norm() < radius; }));
        AirPocketFinder finder;
        const std::vector<AirPocket> pockets = finder.find(grid, kNoSolids);
        QCOMPARE(pockets.size(), std::size_t(1));
        const AirPocket& pocket = pockets[0];
        QVERIFY2((pocket.centre - centre).norm() < kCell,
                 qPrintable(QString("centre off by %1 m").arg((pocket.centre - centre).norm())));
        // Only cells wholly inside the hole are empty: the pocket is smaller than the cavity by
        // about a cell's width all round.
        const double equalVolumeRadius = std::cbrt(3.0 * pocket.volume / (4.0 * M_PI));
        qInfo("pocket of %zu cells, equal-volume radius %.4f m for a %.2f m cavity",
              pocket.cells.size(), equalVolumeRadius, radius);
        QVERIFY(equalVolumeRadius > radius - kCell && equalVolumeRadius < radius);
    }

    void cavityOpenToTheAirIsNoPocket() {
        const Vec3d centre(0.4, 0.3, 0.4);
        NeighborGrid grid(kDomain, kCell);
        // The same cavity with a chimney up through the surface.
        grid.build(poolWithHole(0.6, [&](const Vec3d& x) {
            const bool chimney =
                std::hypot(x.x() - centre.x(), x.z() - centre.z()) < 0.06 && x.y() > centre.y();
            return (x - centre).norm() < 0.1 || chimney;
        }));
        AirPocketFinder finder;
        QVERIFY(finder.find(grid, kNoSolids).empty());
    }

    void airUnderAnOverhangIsAtmosphere() {
        // A cave in the side of a pool: water above it, but open sideways to the air beside the
        // pool, so the flood reaches it from the side (no column reaches it from above).
        NeighborGrid grid(kDomain, kCell);
        grid.build(poolWithHole(0.6, [&](const Vec3d& x) {
            const bool besidePool = x.x() > 0.6;
            const bool cave =
                x.x() > 0.3 && x.y() > 0.2 && x.y() < 0.35 && x.z() > 0.3 && x.z() < 0.5;
            return besidePool || cave;
        }));
        AirPocketFinder finder;
        QVERIFY(finder.find(grid, kNoSolids).empty());
    }

    void cavityInsideASolidIsNoPocket() {
        const Vec3d centre(0.4, 0.3, 0.4);
        NeighborGrid grid(kDomain, kCell);
        grid.build(poolWithHole(0.6, [&](const Vec3d& x) { return (x - centre).norm() < 0.1; }));
        AirPocketFinder finder;
        const auto insideBall = [&](const Vec3d& x) { return (x - centre).norm() < 0.12; };
        QVERIFY(finder.find(grid, insideBall).empty());
    }

    void twoCavitiesAreTwoPocketsLargestFirst() {
        const Vec3d big(0.25, 0.3, 0.4), small(0.6, 0.3, 0.4);
        NeighborGrid grid(kDomain, kCell);
        grid.build(poolWithHole(0.6, [&](const Vec3d& x) {
            return (x - big).norm() < 0.12 || (x - small).norm() < 0.08;
        }));
        AirPocketFinder finder;
        const std::vector<AirPocket> pockets = finder.find(grid, kNoSolids);
        QCOMPARE(pockets.size(), std::size_t(2));
        QVERIFY(pockets[0].volume > pockets[1].volume);
        QVERIFY((pockets[0].centre - big).norm() < kCell);
        QVERIFY((pockets[1].centre - small).norm() < kCell);
    }
};

AIRTRAP_TEST_APPLESS(TestAirPocketFinder)
#include "TestAirPocketFinder.moc"
