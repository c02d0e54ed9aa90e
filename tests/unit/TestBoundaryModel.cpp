// The water marks itself near the moving layer by sweeping around that layer's particles: every
// water particle within the support radius of one must be marked, or the passes would miss its
// boundary force; and the mark must pick out fewer particles than the layer's cell mask, which is
// what it is for.
#include "rigid/MassProperties.h"
#include "rigid/RigidBody.h"
#include "rigid/ShapeSampler.h"
#include "sph/BoundaryModel.h"
#include "support/TestMain.h"

#include <QtTest>
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
        body.makeDynamic(RigidBodyInertia(mass.mass, mass.inertia), Vec3d::Zero(), {});
    }
    return body;
}

//! Random water around the spheres, sorted on its grid as the solver sorts it.
PositionArrays sortedWater(NeighborGrid& grid) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Vec3f> water;
    for (int n = 0; n < 30000; ++n)
        water.emplace_back(0.1f + 0.6f * u(rng), 0.05f + 0.5f * u(rng), 0.05f + 0.4f * u(rng));
    grid.build(water);
    PositionArrays sorted;
    sorted.resize(grid.sortedCount());
    for (std::size_t s = 0; s < grid.sortedCount(); ++s) {
        const Vec3f& x = water[grid.order()[s]];
        sorted.x[s] = x.x();
        sorted.y[s] = x.y();
        sorted.z[s] = x.z();
    }
    return sorted;
}

float nearestDistance(const Vec3f& x, const std::vector<Vec3f>& points) {
    float nearest2 = std::numeric_limits<float>::max();
    for (const Vec3f& p : points)
        nearest2 = std::min(nearest2, (x - p).squaredNorm());
    return std::sqrt(nearest2);
}

} // namespace

class TestBoundaryModel : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void marksExactlyTheWaterWithinTheSupportOfTheMovingLayer() {
        const std::vector<RigidBody> bodies = {sphereBody(Vec3d(0.3, 0.2, 0.25), 0.05, true),
                                               sphereBody(Vec3d(0.5, 0.35, 0.2), 0.03, true),
                                               sphereBody(Vec3d(0.6, 0.1, 0.3), 0.04, false)};
        BoundaryModel model(kModelDomain, kModelSupport, 1000.0f);
        model.rebuild(bodies);
        NeighborGrid grid(kModelDomain, kModelSupport);
        const PositionArrays water = sortedWater(grid);
        model.markWaterNearMovingLayer(grid, water, kModelSupport);

        const BoundaryLayer& moving = model.movingLayer();
        int marked = 0, nearByCell = 0;
        for (std::size_t i = 0; i < water.x.size(); ++i) {
            const Vec3f x = water[i];
            const float distance = nearestDistance(x, moving.positions());
            const bool isMarked = model.mayReach(&moving, i, x);
            if (distance < kModelSupport)
                QVERIFY2(isMarked, qPrintable(QString("unmarked at %1 m").arg(distance)));
            // The mark is a hair wider than the support, never more.
            if (isMarked)
                QVERIFY2(distance < kModelSupport * 1.0001f, qPrintable(QString::number(distance)));
            marked += isMarked;
            nearByCell += moving.reaches(x);
        }
        QVERIFY(marked > 500);
        QVERIFY2(2 * marked < nearByCell,
                 qPrintable(QString("%1 marked, %2 in reached cells").arg(marked).arg(nearByCell)));
    }

    void theStaticLayerKeepsItsCellMask() {
        const std::vector<RigidBody> bodies = {sphereBody(Vec3d(0.6, 0.1, 0.3), 0.04, false)};
        BoundaryModel model(kModelDomain, kModelSupport, 1000.0f);
        model.rebuild(bodies);
        const BoundaryLayer& fixed = model.staticLayer();
        QVERIFY(fixed.size() > 0);
        const Vec3f beside(0.6f, 0.1f, 0.3f + 0.05f);
        const Vec3f far(0.1f, 0.9f, 0.1f);
        QCOMPARE(model.mayReach(&fixed, 0, beside), fixed.reaches(beside));
        QVERIFY(model.mayReach(&fixed, 0, beside));
        QVERIFY(!model.mayReach(&fixed, 0, far));
    }
};

AIRTRAP_TEST_APPLESS(TestBoundaryModel)
#include "TestBoundaryModel.moc"
