// The pairs of water and moving-layer particles are found by sweeping around the layer's
// particles: every pair closer than the support radius must be listed, or the passes would miss
// its boundary force; both views must list the same pairs in ascending order, which is what keeps
// the passes' sums identical to a grid sweep's; and a new search must forget the last one. The
// bodies' contact terms mark the bubbles and the bodies that can sink.
#include "rigid/MassProperties.h"
#include "rigid/RigidBody.h"
#include "rigid/ShapeSampler.h"
#include "sph/BoundaryModel.h"
#include "support/TestMain.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <random>

using namespace airtrap;

namespace {

constexpr double kModelSpacing = 0.02;
constexpr float kModelSupport = 0.04f;
const Aabb kModelDomain{Vec3d(-0.04, -0.04, -0.04), Vec3d(1.04, 1.04, 0.54)};

RigidBody sphereBody(const Vec3d& centre, double radius, bool dynamic) {
    RigidBody body("sphere", ShapeSampler::sampleSphere(radius, kModelSpacing),
                   BodyShape::sphere(radius), RigidPose{centre, Quatd::Identity()});
    if (dynamic) {
        const MassProperties mass = MassProperties::ofSphere(radius, 100.0);
        body.makeDynamic(RigidBodyInertia(mass.mass, mass.inertia), mass.volume, Vec3d::Zero(), {});
    }
    return body;
}

//! Random water around the spheres, sorted on its grid as the solver sorts it.
PositionArrays sortedWater(NeighborGrid& grid, int count = 30000, unsigned seed = 5) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Vec3f> water;
    for (int n = 0; n < count; ++n)
        water.emplace_back(0.1f + 0.6f * u(rng), 0.05f + 0.5f * u(rng), 0.05f + 0.4f * u(rng));
    grid.build(water);
    PositionArrays sorted;
    sorted.gather(water, grid.order());
    return sorted;
}

//! The layer's particles within the support of x, ascending, by brute force.
std::vector<std::uint32_t> boundaryWithinSupport(const Vec3f& x, const BoundaryLayer& layer) {
    std::vector<std::uint32_t> near;
    for (std::uint32_t b = 0; b < layer.size(); ++b)
        if ((x - layer.positions()[b]).squaredNorm() < kModelSupport * kModelSupport)
            near.push_back(b);
    return near;
}

//! Two dynamic spheres, in the moving layer, and a static one, placed.
BoundaryModel modelOfTwoDynamicSpheresAndAStaticOne() {
    const std::vector<RigidBody> bodies = {sphereBody(Vec3d(0.3, 0.2, 0.25), 0.05, true),
                                           sphereBody(Vec3d(0.5, 0.35, 0.2), 0.03, true),
                                           sphereBody(Vec3d(0.6, 0.1, 0.3), 0.04, false)};
    BoundaryModel model(kModelDomain, kModelSupport, 1000.0f);
    model.rebuild(bodies);
    return model;
}

//! Checks that `pairs` lists exactly the pairs of `moving` and `water` within the support (a
//! hair more at most), ascending in both views; returns how many water particles have pairs.
int checkPairs(const MovingLayerPairs& pairs, const BoundaryLayer& moving,
               const PositionArrays& water) {
    int withPairs = 0;
    std::size_t listed = 0;
    for (std::size_t i = 0; i < water.x.size(); ++i) {
        const Vec3f x = water[i];
        const auto near = pairs.boundaryNear(i);
        const std::vector<std::uint32_t> expected = boundaryWithinSupport(x, moving);
        std::size_t next = 0;
        for (std::size_t k = 0; k < near.size(); ++k) {
            const std::uint32_t b = near[k];
            if (k > 0 && near[k - 1] >= b)
                return -1; // not ascending
            // The list is a hair wider than the support, never more.
            if ((x - moving.positions()[b]).norm() >= kModelSupport * 1.0001f)
                return -2;
            const auto inWater = pairs.waterNear(b);
            if (!std::binary_search(inWater.begin(), inWater.end(), std::uint32_t(i)))
                return -3; // the two views disagree
            if (next < expected.size() && expected[next] == b)
                ++next;
        }
        if (next != expected.size())
            return -4; // a pair within the support is missing
        withPairs += near.empty() ? 0 : 1;
        listed += near.size();
    }
    std::size_t byBoundary = 0;
    for (std::size_t b = 0; b < moving.size(); ++b) {
        const auto inWater = pairs.waterNear(b);
        if (!std::is_sorted(inWater.begin(), inWater.end()))
            return -5;
        byBoundary += inWater.size();
    }
    return byBoundary == listed && listed == pairs.pairCount() ? withPairs : -6;
}

} // namespace

class TestBoundaryModel : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void listsExactlyThePairsWithinTheSupportOfTheMovingLayer() {
        BoundaryModel model = modelOfTwoDynamicSpheresAndAStaticOne();
        NeighborGrid grid(kModelDomain, kModelSupport);
        const PositionArrays water = sortedWater(grid);
        model.findMovingLayerPairs(grid, water, kModelSupport);

        const BoundaryLayer& moving = model.movingLayer();
        const int withPairs = checkPairs(model.movingPairs(), moving, water);
        QCOMPARE(std::size_t(withPairs), model.movingPairs().waterCount());
        int nearByCell = 0;
        for (std::size_t i = 0; i < water.x.size(); ++i)
            nearByCell += moving.reaches(water[i]);
        QVERIFY2(withPairs > 500, qPrintable(QString::number(withPairs)));
        // What the list saves: the layer's cell mask would send twice as many through a sweep.
        QVERIFY2(2 * withPairs < nearByCell,
                 qPrintable(
                     QString("%1 with pairs, %2 in reached cells").arg(withPairs).arg(nearByCell)));
    }

    void aNewSearchForgetsTheLastOne() {
        BoundaryModel model = modelOfTwoDynamicSpheresAndAStaticOne();
        NeighborGrid grid(kModelDomain, kModelSupport);
        const PositionArrays first = sortedWater(grid);
        model.findMovingLayerPairs(grid, first, kModelSupport);
        // Fewer particles, elsewhere: last step's marks beyond the new count must not linger.
        const PositionArrays second = sortedWater(grid, 12000, 9);
        model.findMovingLayerPairs(grid, second, kModelSupport);
        const int withPairs = checkPairs(model.movingPairs(), model.movingLayer(), second);
        QVERIFY2(withPairs > 100, qPrintable(QString::number(withPairs)));
        QVERIFY(model.movingPairs().boundaryNear(first.x.size() - 1).empty());
    }

    void theStaticLayerKeepsItsCellMask() {
        const std::vector<RigidBody> bodies = {sphereBody(Vec3d(0.6, 0.1, 0.3), 0.04, false)};
        BoundaryModel model(kModelDomain, kModelSupport, 1000.0f);
        model.rebuild(bodies);
        const BoundaryLayer& fixed = model.staticLayer();
        QVERIFY(fixed.size() > 0);
        const Vec3f beside(0.6f, 0.1f, 0.3f + 0.05f);
        const Vec3f far(0.1f, 0.9f, 0.1f);
        QVERIFY(fixed.reaches(beside));
        QVERIFY(!fixed.reaches(far));
    }

    //! The contact terms say which bodies are bubbles (DFSPH leaves them out of the bodies' step
    //! limit) and which can sink (at least as dense as the water).
    void theTermsMarkBubblesAndSinkingBodies() {
        std::vector<RigidBody> bodies = {sphereBody(Vec3d(0.3, 0.2, 0.25), 0.05, true),
                                         sphereBody(Vec3d(0.6, 0.1, 0.3), 0.04, false),
                                         sphereBody(Vec3d(0.5, 0.35, 0.2), 0.03, true)};
        BoundaryModel model(kModelDomain, kModelSupport, 1000.0f);
        model.rebuild(bodies, 2);
        QVERIFY(!model.contactTerms(0).bubble);
        QVERIFY(!model.contactTerms(1).bubble);
        QVERIFY(model.contactTerms(2).bubble);
        model.rebuild(bodies);
        QVERIFY(!model.contactTerms(2).bubble);
        // The spheres are 100 kg/m³: they float in water and sink in a 50 kg/m³ liquid.
        QVERIFY(!model.contactTerms(0).sinksIn(1000.0));
        QVERIFY(model.contactTerms(0).sinksIn(50.0));
        QVERIFY(!model.contactTerms(1).sinksIn(50.0)); // static
    }
};

AIRTRAP_TEST_APPLESS(TestBoundaryModel)
#include "TestBoundaryModel.moc"
