// Rigid-body dynamics: free fall, torque-free rotation (energy, |L|, the tennis-racket effect),
// impulses and the IBF contact denominator, and the orientation's exponential map.
#include "core/Error.h"
#include "rigid/RigidBodyInertia.h"
#include "rigid/RigidImpulse.h"
#include "rigid/RigidIntegrator.h"
#include "rigid/RotationVector.h"
#include "support/TestMain.h"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace airtrap;

namespace {

const Vec3d kGravity(0.0, -9.81, 0.0);

//! An asymmetric body with principal moments 1 < 2 < 3 kg·m² about the body x, y, z axes.
RigidBodyInertia asymmetricBody() {
    return {4.0, Vec3d(1.0, 2.0, 3.0).asDiagonal().toDenseMatrix()};
}

//! Solid sphere M = 2 kg, R = 0.5 m: I = 2/5 M R² = 0.2 kg·m².
RigidBodyInertia sphere() {
    return {2.0, Mat3d::Identity() * 0.2};
}

Quatd someOrientation() {
    return Quatd(Eigen::AngleAxisd(1.1, Vec3d(0.3, -1.0, 0.4).normalized()));
}

double kineticEnergy(const RigidBodyState& s, const RigidBodyInertia& inertia) {
    return 0.5 * s.angularVelocity.dot(inertia.inertiaWorld(s.orientation) * s.angularVelocity);
}

Vec3d angularMomentumVector(const RigidBodyState& s, const RigidBodyInertia& inertia) {
    return inertia.inertiaWorld(s.orientation) * s.angularVelocity;
}

double angularMomentum(const RigidBodyState& s, const RigidBodyInertia& inertia) {
    return angularMomentumVector(s, inertia).norm();
}

Vec3d bodyFrameOmega(const RigidBodyState& s) {
    return s.orientation.conjugate() * s.angularVelocity;
}

//! Spins the asymmetric body torque-free from body-frame ω₀ and returns the extreme body-frame
//! components seen: (min over time of the component along `axis`, max |other components|).
std::pair<double, double> spinExtremes(const Vec3d& omegaBody, int axis, double dt, int steps) {
    const RigidBodyInertia inertia = asymmetricBody();
    RigidBodyState state;
    state.angularVelocity = omegaBody; // identity orientation: body = world
    double minAlong = omegaBody[axis];
    double maxAcross = 0.0;
    for (int i = 0; i < steps; ++i) {
        RigidIntegrator::step(state, inertia, Vec3d::Zero(), Vec3d::Zero(), Vec3d::Zero(), dt);
        Vec3d w = bodyFrameOmega(state);
        minAlong = std::min(minAlong, w[axis]);
        w[axis] = 0.0;
        maxAcross = std::max(maxAcross, w.cwiseAbs().maxCoeff());
    }
    return {minAlong, maxAcross};
}

} // namespace

class TestRigidDynamics : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void freeFallMatchesTheParabola() {
        // Symplectic Euler under constant acceleration g: V_n = V₀ + g t_n exactly, and
        // X_n = X₀ + V₀ t + ½ g t² + ½ g Δt t, a first-order error of exactly ½ |g| Δt t.
        const RigidBodyInertia inertia = asymmetricBody();
        const Vec3d x0(0.0, 1.0, 0.0), v0(1.0, 2.0, 0.5);
        for (double dt : {1e-3, 5e-4}) {
            RigidBodyState state;
            state.position = x0;
            state.linearVelocity = v0;
            const int steps = static_cast<int>(std::lround(1.0 / dt));
            for (int i = 0; i < steps; ++i)
                RigidIntegrator::step(state, inertia, Vec3d::Zero(), Vec3d::Zero(), kGravity, dt);
            const double t = steps * dt;
            const Vec3d exact = x0 + v0 * t + 0.5 * kGravity * t * t;
            QVERIFY((state.linearVelocity - (v0 + kGravity * t)).norm() < 1e-12);
            QVERIFY((state.position - exact - 0.5 * kGravity * dt * t).norm() < 1e-11);
            QVERIFY((state.position - exact).norm() <= 0.5 * kGravity.norm() * dt * t + 1e-11);
            QVERIFY(state.orientation.isApprox(Quatd::Identity()));
        }
    }

    void forceActsThroughMass() {
        // F = M a: 12 N on 4 kg is 3 m/s², on top of gravity.
        const RigidBodyInertia inertia = asymmetricBody();
        RigidBodyState state;
        RigidIntegrator::step(state, inertia, Vec3d(12.0, 0.0, 0.0), Vec3d::Zero(), kGravity, 0.1);
        QVERIFY((state.linearVelocity - Vec3d(0.3, -0.981, 0.0)).norm() < 1e-15);
        QVERIFY((state.position - 0.1 * state.linearVelocity).norm() < 1e-15);
    }

    void infiniteMassIsNotIntegrated() {
        RigidBodyState state;
        state.linearVelocity = Vec3d(1.0, 0.0, 0.0);
        state.angularVelocity = Vec3d(0.0, 2.0, 0.0);
        const RigidBodyState before = state;
        RigidIntegrator::step(state, RigidBodyInertia::infinite(), Vec3d(1, 2, 3), Vec3d(4, 5, 6),
                              kGravity, 0.01);
        QVERIFY(state == before);
    }

    void torqueSpinsUpAsIdotOmegaEqualsTau() {
        // From rest, one step: Δω = Δt I⁻¹ τ (the gyroscopic term vanishes at ω = 0 to first
        // order).
        const RigidBodyInertia inertia = asymmetricBody();
        RigidBodyState state;
        state.orientation = someOrientation();
        const Vec3d torque(0.5, -1.0, 2.0);
        RigidIntegrator::step(state, inertia, Vec3d::Zero(), torque, Vec3d::Zero(), 1e-3);
        const Vec3d expected = 1e-3 * inertia.inverseInertiaWorld(state.orientation) * torque;
        QVERIFY((state.angularVelocity - expected).norm() < 1e-9 * expected.norm());
    }

    void torqueFreeSpinConservesEnergyAndMomentum() {
        const RigidBodyInertia inertia = asymmetricBody();
        RigidBodyState state;
        state.orientation = someOrientation();
        // Body-frame ω (1, 1, 1): L = (1, 2, 3), far from any principal axis, so ω wanders widely.
        state.angularVelocity = state.orientation * Vec3d(1.0, 1.0, 1.0);
        const double energy0 = kineticEnergy(state, inertia);
        const double momentum0 = angularMomentum(state, inertia);
        const Vec3d omegaBody0 = bodyFrameOmega(state);
        // Without the gyroscopic term ω would stay fixed in the world while the body, and with
        // it I_world, turns about ω: E and |L| keep their values, but the world L = I_world ω
        // turns with the body instead of staying put.
        const Vec3d momentumVector0 = angularMomentumVector(state, inertia);
        RigidBodyState naive = state;
        double naiveDrift = 0.0;
        double drift = 0.0;
        double precession = 0.0;
        for (int i = 0; i < 1000; ++i) {
            RigidIntegrator::step(state, inertia, Vec3d::Zero(), Vec3d::Zero(), Vec3d::Zero(),
                                  0.01);
            naive.orientation =
                RigidIntegrator::advanceOrientation(naive.orientation, naive.angularVelocity, 0.01);
            QVERIFY(std::abs(kineticEnergy(state, inertia) / energy0 - 1.0) < 1e-3);
            QVERIFY(std::abs(angularMomentum(state, inertia) / momentum0 - 1.0) < 1e-3);
            naiveDrift = std::max(naiveDrift,
                                  (angularMomentumVector(naive, inertia) - momentumVector0).norm());
            drift =
                std::max(drift, (angularMomentumVector(state, inertia) - momentumVector0).norm());
            precession = std::max(precession, (bodyFrameOmega(state) - omegaBody0).norm());
        }
        // The implicit midpoint rule conserves both quadratic invariants to rounding.
        QVERIFY(std::abs(kineticEnergy(state, inertia) / energy0 - 1.0) < 1e-10);
        QVERIFY(std::abs(angularMomentum(state, inertia) / momentum0 - 1.0) < 1e-10);
        QVERIFY2(precession > 0.5,
                 qPrintable(QString::number(
                     precession))); // ω did wander in the body: the gyroscopic term was at work
        // The world L vector itself is conserved only to the splitting's second-order error.
        QVERIFY2(drift < 1e-3 * momentum0, qPrintable(QString::number(drift / momentum0)));
        QVERIFY2(naiveDrift > 0.5 * momentum0, qPrintable(QString::number(naiveDrift)));
    }

    void intermediateAxisIsUnstable() {
        // Tennis-racket (Dzhanibekov) effect: a spin about the intermediate axis (I = 2) with a
        // 1e-3 rad/s perturbation flips over within seconds (growth rate
        // ω √((I₂−I₁)(I₃−I₂)/(I₁I₃)) ≈ 2.9/s); about the major axis (I = 3) it stays put.
        const auto [minIntermediate, acrossIntermediate] =
            spinExtremes(Vec3d(1e-3, 5.0, 1e-3), 1, 1e-3, 20000);
        QVERIFY2(minIntermediate < -4.5, qPrintable(QString::number(minIntermediate)));
        QVERIFY(acrossIntermediate > 1.0);
        const auto [minMajor, acrossMajor] = spinExtremes(Vec3d(1e-3, 1e-3, 5.0), 2, 1e-3, 20000);
        QVERIFY2(minMajor > 4.99, qPrintable(QString::number(minMajor)));
        QVERIFY2(acrossMajor < 1e-2, qPrintable(QString::number(acrossMajor)));
        // The minor axis is stable too.
        const auto [minMinor, acrossMinor] = spinExtremes(Vec3d(5.0, 1e-3, 1e-3), 0, 1e-3, 20000);
        QVERIFY(minMinor > 4.99 && acrossMinor < 1e-2);
    }

    void impulseAtCentreChangesOnlyLinearVelocity() {
        const RigidBodyInertia inertia = asymmetricBody();
        RigidBodyState state;
        state.position = Vec3d(1.0, 2.0, 3.0);
        state.orientation = someOrientation();
        state.linearVelocity = Vec3d(0.1, 0.2, 0.3);
        state.angularVelocity = Vec3d(-1.0, 0.5, 0.25);
        RigidBodyState expected = state;
        const Vec3d impulse(2.0, -4.0, 8.0);
        expected.linearVelocity += impulse / 4.0;
        RigidImpulse::apply(state, inertia, impulse, state.position);
        QVERIFY(state == expected);
    }

    void offCentreImpulseOnSphere() {
        // r = (0.3, 0.4, 0) on the surface of R = 0.5, J = (1, −2, 0.5) N·s:
        // r × J = (0.2, −0.15, −1.0), Δω = (r × J)/0.2 = (1, −0.75, −5), ΔV = J/2.
        RigidBodyState state;
        state.position = Vec3d(1.0, 1.0, 1.0);
        state.orientation = someOrientation(); // a sphere's inertia is the same in every frame
        RigidImpulse::apply(state, sphere(), Vec3d(1.0, -2.0, 0.5),
                            state.position + Vec3d(0.3, 0.4, 0.0));
        QVERIFY((state.angularVelocity - Vec3d(1.0, -0.75, -5.0)).norm() < 1e-12);
        QVERIFY((state.linearVelocity - Vec3d(0.5, -1.0, 0.25)).norm() < 1e-15);
        RigidBodyState fixed;
        RigidImpulse::apply(fixed, RigidBodyInertia::infinite(), Vec3d(1, 2, 3), Vec3d(0, 1, 0));
        QVERIFY(fixed == RigidBodyState{});
    }

    void contactDenominatorOnSphere() {
        const Vec3d n(0.0, 1.0, 0.0);
        // Head-on: r ∥ n, so r × n = 0 and K = 1/M exactly.
        QCOMPARE(RigidImpulse::inverseEffectiveMass(sphere(), someOrientation(), n, -0.5 * n), 0.5);
        // Off-centre, by hand: for I = c·1, n·((r × n)/c × r) = |r × n|²/c; r × n = (0, 0, 0.3),
        // so K = 0.5 + 0.09/0.2 = 0.95.
        const double k = RigidImpulse::inverseEffectiveMass(sphere(), someOrientation(), n,
                                                            Vec3d(0.3, 0.4, 0.0));
        QVERIFY(std::abs(k - 0.95) < 1e-12);
        QCOMPARE(RigidImpulse::inverseEffectiveMass(RigidBodyInertia::infinite(), Quatd::Identity(),
                                                    n, Vec3d(0.3, 0.4, 0.0)),
                 0.0);
    }

    void contactDenominatorIsTheVelocityResponse() {
        // K is the change of the contact point's normal velocity per unit normal impulse, which
        // is what makes j = −(1+ε) u_n / K give the restitution ε.
        const RigidBodyInertia inertia = asymmetricBody();
        RigidBodyState state;
        state.position = Vec3d(0.2, -0.1, 0.4);
        state.orientation = someOrientation();
        const Vec3d r(0.3, -0.2, 0.5);
        const Vec3d n = Vec3d(1.0, 2.0, -0.5).normalized();
        const auto pointVelocity = [&](const RigidBodyState& s) -> Vec3d {
            return s.linearVelocity + s.angularVelocity.cross(r);
        };
        const Vec3d before = pointVelocity(state);
        RigidImpulse::apply(state, inertia, n, state.position + r);
        const double k = RigidImpulse::inverseEffectiveMass(inertia, state.orientation, n, r);
        QVERIFY(std::abs((pointVelocity(state) - before).dot(n) - k) < 1e-14);
        QVERIFY(k > inertia.inverseMass());
    }

    void orientationStaysUnitLength() {
        const RigidBodyInertia inertia = asymmetricBody();
        RigidBodyState state;
        state.angularVelocity = Vec3d(3.0, -2.0, 5.0);
        double worst = 0.0;
        for (int i = 0; i < 100000; ++i) {
            RigidIntegrator::step(state, inertia, Vec3d::Zero(), Vec3d(0.01, 0.0, -0.02),
                                  Vec3d::Zero(), 1e-3);
            worst = std::max(worst, std::abs(state.orientation.norm() - 1.0));
        }
        QVERIFY2(worst < 1e-14, qPrintable(QString::number(worst)));
        QVERIFY(state.angularVelocity.allFinite());
    }

    void exponentialMapMatchesAnalyticRotation() {
        // Constant ω: n steps of q ← exp(ω Δt) q are the rotation by |ω| t about ω/|ω|.
        const Vec3d omega(0.3, -1.2, 2.0);
        const Quatd q0 = someOrientation();
        const double dt = 1e-3;
        const int steps = 10000;
        Quatd q = q0;
        for (int i = 0; i < steps; ++i)
            q = RigidIntegrator::advanceOrientation(q, omega, dt);
        const double t = steps * dt;
        const Quatd analytic = Quatd(Eigen::AngleAxisd(omega.norm() * t, omega.normalized())) * q0;
        QVERIFY2(q.angularDistance(analytic) < 1e-9,
                 qPrintable(QString::number(q.angularDistance(analytic))));
        // Through the full step: a sphere has no gyroscopic torque, so ω stays constant.
        RigidBodyState state;
        state.orientation = q0;
        state.angularVelocity = omega;
        for (int i = 0; i < steps; ++i)
            RigidIntegrator::step(state, sphere(), Vec3d::Zero(), Vec3d::Zero(), Vec3d::Zero(), dt);
        const double omegaDrift = (state.angularVelocity - omega).norm();
        // Only rounding of the frame changes, about 1e-16 |ω| per step.
        QVERIFY2(omegaDrift < 1e-11, qPrintable(QString::number(omegaDrift)));
        QVERIFY(state.orientation.angularDistance(analytic) < 1e-9);
    }

    void rotationVectorRoundTrip() {
        QVERIFY(RotationVector::toQuaternion(Vec3d::Zero()) == Quatd::Identity());
        for (double angle : {0.0, 1e-14, 1e-7, 1e-3, 0.5, 2.0, 3.1})
            for (const Vec3d& axis : {Vec3d(1, 0, 0), Vec3d(0.3, -0.8, 0.5).normalized()}) {
                const Vec3d phi = angle * axis;
                const Quatd q = RotationVector::toQuaternion(phi);
                QVERIFY(std::abs(q.norm() - 1.0) < 1e-15);
                QVERIFY(q.isApprox(Quatd(Eigen::AngleAxisd(angle, axis)), 1e-15) || angle == 0.0);
                QVERIFY((RotationVector::fromQuaternion(q) - phi).norm() < 1e-14);
                // −q is the same rotation; the shortest arc is taken either way.
                QVERIFY((RotationVector::fromQuaternion(Quatd(-q.coeffs())) - phi).norm() < 1e-14);
            }
    }

    void inertiaIsChecked() {
        const auto throws = [](double mass, const Mat3d& tensor) {
            try {
                RigidBodyInertia(mass, tensor);
            } catch (const Error& error) {
                return error.kind() == ErrorKind::InvalidInput;
            }
            return false;
        };
        QVERIFY(throws(0.0, Mat3d::Identity()));
        QVERIFY(throws(std::numeric_limits<double>::infinity(), Mat3d::Identity()));
        QVERIFY(throws(1.0, Vec3d(1.0, -1.0, 1.0).asDiagonal().toDenseMatrix()));
        Mat3d skewed = Mat3d::Identity();
        skewed(0, 1) = 0.5;
        QVERIFY(throws(1.0, skewed));
        // A general (non-principal) tensor: world inverse inertia is the inverse of R I Rᵀ.
        Mat3d tensor;
        tensor << 2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.0;
        const RigidBodyInertia inertia(3.0, tensor);
        const Quatd q = someOrientation();
        QVERIFY(
            (inertia.inverseInertiaWorld(q) * inertia.inertiaWorld(q) - Mat3d::Identity()).norm() <
            1e-14);
        QVERIFY(RigidBodyInertia::infinite().isInfinite());
        QVERIFY(RigidBodyInertia::infinite().inverseInertiaWorld(q) == Mat3d::Zero());
    }
};

AIRTRAP_TEST_APPLESS(TestRigidDynamics)
#include "TestRigidDynamics.moc"
