// Bubble–bubble impulses with a non-positive coefficient of restitution (paper §3.3.2): two
// bubbles fly at each other with no water and no gravity, so only their mutual impulse can change
// their velocities. The bubbles' own step is run on its own (BubbleDynamics, bodies moved
// ballistically): in a simulation a bubble out of the water is deleted at once (docs/METHOD.md).
//  - ε = −1: they pass through each other; the velocities do not change by a single bit.
//  - −1 < ε < 0: a weak repulsion: they slow down and overlap, the more the nearer ε₂ is to −1;
//    momentum is conserved, and they never bounce apart. (The impulse acts at every step they
//    touch, taking (1 + ε₂) of the approach each time, so even ε₂ = −0.9 stops them within a
//    tenth of a second.)
//  - ε = 0: the approach stops at contact (no overlap beyond a step's travel).
#include "BubbleTestSupport.h"
#include "bubbles/BubbleDynamics.h"
#include "support/TestMain.h"

#include <QtTest>

using namespace airtrap;

namespace {

constexpr double kRadius = 0.05;
constexpr double kSpeed = 0.5;
//! s, about the solver's step for 2 cm water at max_speed 2 m/s.
constexpr double kFlightStep = 2.0e-4;

struct Flight {
    double closestDistance = 1e9;
    Vec3d finalVelocityA = Vec3d::Zero();
    Vec3d finalVelocityB = Vec3d::Zero();
    double largestMomentumChange = 0.0; //!< kg·m/s, of the pair's total
    bool separatedAfterContact = false;
};

Flight fly(double approaching, double overlapping) {
    Scene scene;
    scene.solver.particleSpacing = 0.02;
    scene.bubbles.enabled = true;
    scene.bubbles.approachRestitution = approaching;
    scene.bubbles.overlapRestitution = overlapping;
    BubbleDynamics dynamics(scene.bubbles, scene.solver,
                            CubicSplineKernel(float(scene.supportRadius())));
    std::vector<RigidBody> bodies;
    dynamics.syncBodies(
        bodies, 0,
        {test::bubbleAt(0, Vec3d(0.35, 0.35, 0.35), kRadius, Vec3d(kSpeed, 0, 0)),
         test::bubbleAt(1, Vec3d(0.65, 0.35, 0.35), kRadius, Vec3d(-kSpeed, 0, 0))});
    Flight flight;
    bool touched = false;
    for (double time = 0.0; time < 0.4; time += kFlightStep) {
        dynamics.applyPairImpulses(bodies, 0);
        for (RigidBody& body : bodies) {
            RigidBodyState state = body.state();
            state.position += kFlightStep * state.linearVelocity;
            body.setState(state);
        }
        const RigidBodyState a = bodies[0].state();
        const RigidBodyState b = bodies[1].state();
        const double distance = (a.position - b.position).norm();
        touched = touched || distance < 2.0 * kRadius;
        const double approach = (b.linearVelocity - a.linearVelocity).x();
        flight.separatedAfterContact = flight.separatedAfterContact || (touched && approach > 0);
        flight.closestDistance = std::min(flight.closestDistance, distance);
        const double momentum = (a.linearVelocity + b.linearVelocity).norm(); // equal masses
        flight.largestMomentumChange = std::max(flight.largestMomentumChange, momentum);
        flight.finalVelocityA = a.linearVelocity;
        flight.finalVelocityB = b.linearVelocity;
    }
    return flight;
}

} // namespace

class TestBubbleInteraction : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void minusOneGivesNoInteraction() {
        const Flight flight = fly(-1.0, -1.0);
        // They met head on and passed through each other untouched.
        QVERIFY(flight.closestDistance < 0.01);
        QCOMPARE(flight.finalVelocityA, Vec3d(kSpeed, 0, 0));
        QCOMPARE(flight.finalVelocityB, Vec3d(-kSpeed, 0, 0));
    }

    void negativeRestitutionRepelsWeakly() {
        const Flight flight = fly(-0.6, -0.9);
        const double approach = (flight.finalVelocityA - flight.finalVelocityB).x();
        qInfo("closest distance %.4f m (touching at %.3f), approach speed %.4f m/s of %.1f",
              flight.closestDistance, 2 * kRadius, approach, 2 * kSpeed);
        QVERIFY2(flight.closestDistance < 2.0 * kRadius - 1e-3, "the bubbles did not overlap");
        QVERIFY2(approach < 0.5 * 2 * kSpeed, "the repulsion did not slow them down");
        QVERIFY2(!flight.separatedAfterContact, "non-positive restitution made them bounce");
        QVERIFY(flight.largestMomentumChange < 1e-12);
        // Nearer −1 the repulsion is weaker still: they overlap further.
        const Flight weaker = fly(-0.6, -0.99);
        qInfo("with ε₂ = −0.99: closest distance %.4f m", weaker.closestDistance);
        QVERIFY(weaker.closestDistance < flight.closestDistance - 1e-3);
        QVERIFY(!weaker.separatedAfterContact);
    }

    void zeroRestitutionStopsTheApproach() {
        const Flight flight = fly(0.0, 0.0);
        const double approach = (flight.finalVelocityA - flight.finalVelocityB).x();
        QVERIFY(std::abs(approach) < 1e-12);
        // They stop within one step's travel of touching.
        QVERIFY(flight.closestDistance > 2.0 * kRadius - 0.01);
        QVERIFY(!flight.separatedAfterContact);
    }
};

AIRTRAP_TEST_APPLESS(TestBubbleInteraction)
#include "TestBubbleInteraction.moc"
