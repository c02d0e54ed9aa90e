// The rule that judges where a bubble is (docs/VALIDATION.md, "Where the bubbles live"): 26 probes
// at r + spacing/2, wet when water lies within one spacing. A bubble deep in lattice water is in
// water with every probe wet, one whose centre sits on the free surface floats, one above the
// water is airborne; the thresholds fall at 13 and 6.5 probes.
#include "bubbles/BubbleImmersion.h"
#include "support/TestMain.h"

#include <QtTest>

using namespace airtrap;

namespace {

constexpr double kImmersionSpacing = 0.02;
const Aabb kImmersionDomain{Vec3d(0.0, 0.0, 0.0), Vec3d(0.6, 0.8, 0.6)};

//! Lattice water below `surface` (m), with a spherical hole of `hole` m at `centre`.
struct LatticePool {
    NeighborGrid grid{kImmersionDomain, 2.0f * float(kImmersionSpacing)};
    PositionArrays sorted;

    LatticePool(double surface, const Vec3d& centre, double hole) {
        std::vector<Vec3f> points;
        for (int k = 0; k < 30; ++k)
            for (int j = 0; j < 40; ++j)
                for (int i = 0; i < 30; ++i) {
                    const Vec3d x = (Vec3d(i, j, k) + Vec3d::Constant(0.5)) * kImmersionSpacing;
                    if (x.y() < surface && (x - centre).norm() >= hole)
                        points.push_back(x.cast<float>());
                }
        grid.build(points);
        sorted.gather(points, grid.order());
    }
};

} // namespace

class TestBubbleImmersion : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void probesPointAtACubesFacesEdgesAndCorners() {
        const auto& directions = BubbleImmersion::directions();
        int faces = 0, edges = 0, corners = 0;
        for (const Vec3d& d : directions) {
            QVERIFY(std::abs(d.norm() - 1.0) < 1e-12);
            const int axes = int((d.array().abs() > 1e-9).count());
            faces += axes == 1;
            edges += axes == 2;
            corners += axes == 3;
        }
        QCOMPARE(faces, 6);
        QCOMPARE(edges, 12);
        QCOMPARE(corners, 8);
        // Above the equator: the top face, 4 edges and 4 corners.
        const BubbleImmersion::WetProbes upper = BubbleImmersion::hemisphere(Vec3d::UnitY());
        QCOMPARE(int(upper.count()), 9);
        for (int k = 0; k < BubbleImmersion::kProbeCount; ++k)
            QCOMPARE(upper.test(k), directions[k].y() > 0.0);
    }

    void thresholdsFallAtHalfAndAQuarter() {
        using P = BubbleImmersion::Placement;
        QCOMPARE(BubbleImmersion::placement(26), P::InWater);
        QCOMPARE(BubbleImmersion::placement(13), P::InWater);
        QCOMPARE(BubbleImmersion::placement(12), P::Floating);
        QCOMPARE(BubbleImmersion::placement(7), P::Floating);
        QCOMPARE(BubbleImmersion::placement(6), P::Airborne);
        QCOMPARE(BubbleImmersion::placement(0), P::Airborne);
    }

    void bubbleDeepInWaterHasEveryProbeWet() {
        const Vec3d centre(0.3, 0.3, 0.3);
        const double radius = 0.04;
        // Water against the bubble: no lattice point nearer than half a spacing to its surface.
        const LatticePool pool(0.7, centre, radius + 0.5 * kImmersionSpacing);
        const BubbleImmersion immersion(kImmersionSpacing);
        const auto wet = immersion.measure(centre, radius, pool.grid, pool.sorted);
        QCOMPARE(int(wet.count()), 26);
    }

    void bubbleBreakingTheSurfaceFloatsAndAboveItIsAirborne() {
        const double radius = 0.04;
        const double surface = 0.4;
        const BubbleImmersion immersion(kImmersionSpacing);
        const auto wetAt = [&](double height) {
            const Vec3d centre(0.3, surface + height, 0.3);
            const LatticePool pool(surface, centre, radius + 0.5 * kImmersionSpacing);
            const int wet = int(immersion.measure(centre, radius, pool.grid, pool.sorted).count());
            qInfo("centre %+.3f m from the surface: %d of 26 probes wet", height, wet);
            return BubbleImmersion::placement(wet);
        };
        using P = BubbleImmersion::Placement;
        // Half under: the 9 probes below the equator and the 8 on it reach the water.
        QCOMPARE(wetAt(0.0), P::InWater);
        // Two thirds out: the 9 lower probes only.
        QCOMPARE(wetAt(0.5 * radius), P::Floating);
        // Resting on the surface, its lowest point a spacing above the top layer: out of it.
        QCOMPARE(wetAt(radius + kImmersionSpacing), P::Airborne);
    }
};

AIRTRAP_TEST_APPLESS(TestBubbleImmersion)
#include "TestBubbleImmersion.moc"
