// Non-positive restitution between bubbles (paper §3.3.2): ε = −1 gives exactly no interaction;
// −1 < ε < 0 a weak repulsion that slows the approach without stopping it, so bubbles overlap;
// ε₂ rules once they overlap; bubbles moving apart or apart are left alone.
#include "bubbles/BubblePairImpulse.h"
#include "core/Error.h"
#include "rigid/MassProperties.h"
#include "support/TestMain.h"

#include <QtTest>

using namespace airtrap;

namespace {

constexpr double kRadius = 0.01;

RigidBodyInertia bubbleInertia() {
    const MassProperties mass = MassProperties::ofSphere(kRadius, 100.0); // 0.1 of water
    return RigidBodyInertia(mass.mass, mass.inertia);
}

//! Two bubbles `gap` apart (negative: overlapping), closing at 0.2 m/s along x.
std::pair<RigidBodyState, RigidBodyState> closingPair(double gap) {
    RigidBodyState a, b;
    a.position = Vec3d(0.0, 0.0, 0.0);
    b.position = Vec3d(2 * kRadius + gap, 0.0, 0.0);
    a.linearVelocity = Vec3d(0.1, 0.0, 0.0);
    b.linearVelocity = Vec3d(-0.1, 0.0, 0.0);
    return {a, b};
}

} // namespace

class TestBubblePairImpulse : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void minusOneIsNoInteraction() {
        const RigidBodyInertia inertia = bubbleInertia();
        const BubblePairImpulse pair(-1.0, -1.0);
        for (double gap : {0.0, -0.005, -0.015}) {
            auto [a, b] = closingPair(gap);
            const RigidBodyState a0 = a, b0 = b;
            QCOMPARE(pair.apply(a, inertia, kRadius, b, inertia, kRadius), 0.0);
            QVERIFY(a == a0 && b == b0);
        }
    }

    void negativeRestitutionOnlySlowsTheApproach() {
        const RigidBodyInertia inertia = bubbleInertia();
        const BubblePairImpulse pair(-0.6, -0.3);
        auto [a, b] = closingPair(0.0); // touching
        const double j = pair.apply(a, inertia, kRadius, b, inertia, kRadius);
        QVERIFY(j > 0.0);
        // uₙ' = −ε uₙ: with ε₁ = −0.6 the closing speed 0.2 m/s becomes 0.12 m/s, still closing.
        const double closing = (b.linearVelocity - a.linearVelocity).x();
        QVERIFY(std::abs(closing - (-0.12)) < 1e-12);
        // Momentum is exchanged, not made.
        QVERIFY(std::abs((a.linearVelocity + b.linearVelocity).x()) < 1e-15);
    }

    void overlappingBubblesUseTheSecondCoefficient() {
        const RigidBodyInertia inertia = bubbleInertia();
        const BubblePairImpulse pair(-0.6, -0.3);
        auto [a, b] = closingPair(-0.004); // 4 mm into each other
        pair.apply(a, inertia, kRadius, b, inertia, kRadius);
        QVERIFY(std::abs((b.linearVelocity - a.linearVelocity).x() - (-0.06)) < 1e-12);
    }

    void separatingOrApartBubblesAreLeftAlone() {
        const RigidBodyInertia inertia = bubbleInertia();
        const BubblePairImpulse pair(-0.5, 0.0);
        auto [a, b] = closingPair(0.001); // 1 mm apart
        QCOMPARE(pair.apply(a, inertia, kRadius, b, inertia, kRadius), 0.0);
        auto [c, d] = closingPair(-0.002);
        std::swap(c.linearVelocity, d.linearVelocity); // moving apart while overlapping
        QCOMPARE(pair.apply(c, inertia, kRadius, d, inertia, kRadius), 0.0);
    }

    void positiveRestitutionIsRefused() {
        QVERIFY_THROWS_EXCEPTION(Error, BubblePairImpulse(0.2, 0.0));
        QVERIFY_THROWS_EXCEPTION(Error, BubblePairImpulse(-0.5, -1.5));
    }
};

AIRTRAP_TEST_APPLESS(TestBubblePairImpulse)
#include "TestBubblePairImpulse.moc"
