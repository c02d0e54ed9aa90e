// A boundary layer sorts its particles on a grid cut to the cells around them, not the whole
// domain: the water must still find every boundary neighbour through it, and skip it far away.
#include "rigid/RigidBody.h"
#include "rigid/ShapeSampler.h"
#include "sph/BoundaryLayer.h"
#include "support/TestMain.h"

#include <QtTest>
#include <random>

using namespace airtrap;

namespace {

constexpr double kLayerSpacing = 0.02;
constexpr float kSupport = 0.04f;
const Aabb kGridDomain{Vec3d(-0.04, -0.04, -0.04), Vec3d(1.04, 1.04, 0.54)};

RigidBody sphereAt(const Vec3d& centre, double radius) {
    return RigidBody("sphere", ShapeSampler::sampleSphere(radius, kLayerSpacing),
                     BodyShape::sphere(radius), RigidPose{centre, Quatd::Identity()});
}

} // namespace

class TestBoundaryLayer : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void waterFindsEveryBoundaryNeighbourThroughTheCutGrid() {
        const std::vector<RigidBody> bodies = {sphereAt(Vec3d(0.3, 0.2, 0.25), 0.05),
                                               sphereAt(Vec3d(0.45, 0.3, 0.2), 0.03)};
        BoundaryLayer layer(kGridDomain, kSupport, 1000.0f);
        layer.rebuild(bodies, {0, 1});
        QVERIFY(layer.size() > 50);
        const NeighborGrid whole(kGridDomain, kSupport);
        QVERIFY2(
            layer.grid().cellTotal() * 8 < whole.cellTotal(),
            qPrintable(
                QString("%1 cells of %2").arg(layer.grid().cellTotal()).arg(whole.cellTotal())));

        std::mt19937 rng(9);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        int near = 0;
        for (int n = 0; n < 20000; ++n) {
            // Around the spheres, where the water meets them, and sometimes anywhere.
            const Vec3f x = n % 4 == 0 ? Vec3f(u(rng), u(rng), 0.5f * u(rng))
                                       : Vec3f(0.2f + 0.35f * u(rng), 0.1f + 0.3f * u(rng),
                                               0.1f + 0.25f * u(rng));
            std::size_t expected = 0;
            for (const Vec3f& b : layer.positions())
                expected += (x - b).squaredNorm() < kSupport * kSupport;
            if (!layer.reaches(x)) {
                QCOMPARE(expected, std::size_t(0));
                continue;
            }
            std::size_t found = 0;
            layer.grid().forEachNeighborRange(
                x, kSupport, [&](std::uint32_t begin, std::uint32_t end) {
                    for (std::uint32_t b = begin; b < end; ++b)
                        found += (x - layer.positions()[b]).squaredNorm() < kSupport * kSupport;
                });
            QCOMPARE(found, expected);
            near += expected > 0;
        }
        QVERIFY(near > 1000);
        QVERIFY(!layer.reaches(Vec3f(0.9f, 0.9f, 0.45f)));
    }

    void anEmptyLayerReachesNothing() {
        BoundaryLayer layer(kGridDomain, kSupport, 1000.0f);
        layer.rebuild({}, {});
        QCOMPARE(layer.size(), std::size_t(0));
        QVERIFY(!layer.reaches(Vec3f(0.5f, 0.5f, 0.25f)));
    }
};

AIRTRAP_TEST_APPLESS(TestBoundaryLayer)
#include "TestBoundaryLayer.moc"
