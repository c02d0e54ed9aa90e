// Kinematic motion: a body on a prescribed path hits its keyframes exactly, moves continuously,
// and its velocity is the one that carries the solver's integration along the path.
#include "core/Error.h"
#include "rigid/KinematicMotion.h"
#include "rigid/RigidIntegrator.h"
#include "support/TestMain.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <random>

using namespace airtrap;

namespace {

using Keyframe = KeyframedPath::Keyframe;

Quatd turn(double angle, const Vec3d& axis) {
    return Quatd(Eigen::AngleAxisd(angle, axis.normalized()));
}

//! Four keyframes with uneven spacing, a turn of 170° in one segment and a pause in another.
std::vector<Keyframe> someKeyframes() {
    return {{0.5, Vec3d(0.0, 1.0, 0.0), turn(0.3, Vec3d(0, 1, 0))},
            {0.9, Vec3d(0.4, 1.2, -0.1), turn(1.2, Vec3d(1, 1, 0))},
            {2.0, Vec3d(0.4, 1.2, -0.1), turn(1.2, Vec3d(1, 1, 0))},
            {2.35, Vec3d(-0.3, 0.7, 0.8), turn(1.2, Vec3d(1, 1, 0)) * turn(2.967, Vec3d(0, 0, 1))}};
}

double distance(const RigidPose& a, const RigidPose& b) {
    return std::max((a.position - b.position).norm(), a.orientation.angularDistance(b.orientation));
}

double distance(const RigidPose& pose, const Keyframe& key) {
    return distance(pose, RigidPose{key.position, key.orientation});
}

//! The largest linear and angular speed over the path's segments.
std::pair<double, double> maxSpeeds(const KeyframedPath& path) {
    double linear = 0.0, angular = 0.0;
    for (const Keyframe& key : path.keyframes()) {
        const RigidVelocity v = path.velocityAt(key.time);
        linear = std::max(linear, v.linear.norm());
        angular = std::max(angular, v.angular.norm());
    }
    return {linear, angular};
}

//! Steps of random length in [1e-4, 0.07] s that never cross a keyframe: each ends on the next
//! keyframe's time if it would pass it, as the solver's last sub-step ends on a frame time.
std::vector<double> stepTimes(const KeyframedPath& path, double end, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> length(1e-4, 0.07);
    std::vector<double> times{0.0};
    while (times.back() < end) {
        double next = std::min(times.back() + length(random), end);
        for (const Keyframe& key : path.keyframes())
            if (times.back() < key.time && key.time < next)
                next = key.time;
        times.push_back(next);
    }
    return times;
}

bool throwsInvalidInput(const std::vector<Keyframe>& keys) {
    try {
        KeyframedPath path(keys);
    } catch (const Error& error) {
        return error.kind() == ErrorKind::InvalidInput;
    }
    return false;
}

} // namespace

class TestKinematicMotion : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void keyframesAreHitExactly() {
        const KeyframedPath path(someKeyframes());
        for (const Keyframe& key : path.keyframes())
            QVERIFY(path.poseAt(key.time) == (RigidPose{key.position, key.orientation}));
        // Sampling poseAt at arbitrary Δt: every keyframe time reached gives its keyframe.
        int hits = 0;
        for (double t : stepTimes(path, 3.0, 1))
            for (const Keyframe& key : path.keyframes())
                if (t == key.time) {
                    QVERIFY(distance(path.poseAt(t), key) < 1e-12);
                    ++hits;
                }
        QCOMPARE(hits, 4);
    }

    void pathIsContinuous() {
        // |Δpose| ≤ speed × Δt for every step, across keyframes too, for steps of any size.
        const KeyframedPath path(someKeyframes());
        const auto [linear, angular] = maxSpeeds(path);
        for (unsigned seed : {2u, 3u, 4u}) {
            std::mt19937 random(seed);
            std::uniform_real_distribution<double> length(1e-9, 0.05);
            double t = 0.0;
            while (t < 3.0) {
                const double dt = length(random);
                const RigidPose a = path.poseAt(t), b = path.poseAt(t + dt);
                QVERIFY((a.position - b.position).norm() <= linear * dt + 1e-12);
                QVERIFY(a.orientation.angularDistance(b.orientation) <= angular * dt + 1e-12);
                t += dt;
            }
        }
        // Just before and just after each keyframe.
        for (const Keyframe& key : path.keyframes()) {
            QVERIFY(distance(path.poseAt(key.time - 1e-10), key) < 1e-9);
            QVERIFY(distance(path.poseAt(key.time + 1e-10), key) < 1e-9);
        }
    }

    void kinematicBodyFollowsItsPathExactly() {
        // Moved as the solver moves it, X += V Δt and q ← exp(ω Δt) q with the path's velocity
        // at the start of each step, the body stays on poseAt and lands on every keyframe.
        const KeyframedPath path(someKeyframes());
        for (unsigned seed : {5u, 6u}) {
            const std::vector<double> times = stepTimes(path, 3.0, seed);
            RigidPose pose = path.poseAt(0.0);
            double worst = 0.0;
            for (std::size_t i = 1; i < times.size(); ++i) {
                const double dt = times[i] - times[i - 1];
                const RigidVelocity v = path.velocityAt(times[i - 1]);
                pose.position += v.linear * dt;
                pose.orientation =
                    RigidIntegrator::advanceOrientation(pose.orientation, v.angular, dt);
                worst = std::max(worst, distance(pose, path.poseAt(times[i])));
            }
            QVERIFY2(worst < 1e-12, qPrintable(QString::number(worst)));
            QVERIFY(distance(pose, path.keyframes().back()) < 1e-12);
        }
    }

    void velocityIsTheSegmentFiniteDifference() {
        const KeyframedPath path(someKeyframes());
        const std::vector<Keyframe>& keys = path.keyframes();
        for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
            const double duration = keys[i + 1].time - keys[i].time;
            for (double s : {0.0, 0.3, 0.999}) {
                const RigidVelocity v = path.velocityAt(keys[i].time + s * duration);
                QVERIFY((v.linear - (keys[i + 1].position - keys[i].position) / duration).norm() <
                        1e-12);
                const Quatd end =
                    RigidIntegrator::advanceOrientation(keys[i].orientation, v.angular, duration);
                QVERIFY(end.angularDistance(keys[i + 1].orientation) < 1e-12);
            }
        }
        // Slerp: halfway through a segment is Eigen's spherical interpolation at ½.
        const RigidPose half = path.poseAt(0.5 * (keys[2].time + keys[3].time));
        QVERIFY(half.orientation.angularDistance(
                    keys[2].orientation.slerp(0.5, keys[3].orientation)) < 1e-12);
        QVERIFY((half.position - 0.5 * (keys[2].position + keys[3].position)).norm() < 1e-12);
    }

    void poseIsHeldOutsideTheKeyframes() {
        const KeyframedPath path(someKeyframes());
        const Keyframe& first = path.keyframes().front();
        const Keyframe& last = path.keyframes().back();
        for (double t : {-1.0, 0.0, 0.4999})
            QVERIFY(path.poseAt(t) == (RigidPose{first.position, first.orientation}) &&
                    path.velocityAt(t) == RigidVelocity{});
        for (double t : {last.time, 2.5, 100.0})
            QVERIFY(path.poseAt(t) == (RigidPose{last.position, last.orientation}) &&
                    path.velocityAt(t) == RigidVelocity{});
        // A pause between two equal keyframes is at rest.
        QVERIFY(path.velocityAt(1.5) == RigidVelocity{});
        // A single keyframe is a body that never moves.
        const KeyframedPath still({{1.0, Vec3d(1, 2, 3), turn(0.5, Vec3d(1, 0, 0))}});
        QVERIFY(still.poseAt(0.0) == still.poseAt(5.0) && still.velocityAt(1.0) == RigidVelocity{});
    }

    void constantVelocityIsExact() {
        const RigidPose start{Vec3d(1.0, 0.5, -0.2), turn(0.4, Vec3d(1, 0, 1))};
        const KinematicMotion::ConstantVelocity velocity{Vec3d(0.3, -0.1, 0.2),
                                                         Vec3d(0.0, 2.5, 0.5)};
        const KinematicMotion motion(start, velocity);
        for (double t : {0.0, 0.37, 4.0}) {
            const RigidPose pose = motion.poseAt(t);
            QVERIFY((pose.position - (start.position + velocity.linear * t)).norm() < 1e-15);
            const Quatd analytic =
                turn(velocity.angular.norm() * t, velocity.angular) * start.orientation;
            QVERIFY(pose.orientation.angularDistance(analytic) < 1e-14);
            QVERIFY(motion.velocityAt(t) == (RigidVelocity{velocity.linear, velocity.angular}));
        }
        // Integrated by the solver at arbitrary steps, it stays on poseAt.
        std::mt19937 random(7);
        std::uniform_real_distribution<double> length(1e-4, 0.05);
        RigidPose pose = motion.poseAt(0.0);
        double t = 0.0;
        while (t < 3.0) {
            const double dt = length(random);
            const RigidVelocity v = motion.velocityAt(t);
            pose.position += v.linear * dt;
            pose.orientation = RigidIntegrator::advanceOrientation(pose.orientation, v.angular, dt);
            t += dt;
        }
        QVERIFY2(distance(pose, motion.poseAt(t)) < 1e-12,
                 qPrintable(QString::number(distance(pose, motion.poseAt(t)))));
    }

    void keyframedMotionDelegatesToItsPath() {
        const KeyframedPath path(someKeyframes());
        const KinematicMotion motion(path);
        for (double t : {0.0, 0.7, 2.1, 9.0}) {
            QVERIFY(motion.poseAt(t) == path.poseAt(t));
            QVERIFY(motion.velocityAt(t) == path.velocityAt(t));
        }
    }

    void invalidKeyframesAreRefused() {
        QVERIFY(throwsInvalidInput({}));
        std::vector<Keyframe> keys = someKeyframes();
        keys[2].time = keys[1].time;
        QVERIFY(throwsInvalidInput(keys));
        keys = someKeyframes();
        keys[1].position.x() = std::nan("");
        QVERIFY(throwsInvalidInput(keys));
        keys = someKeyframes();
        keys[0].orientation = Quatd(0, 0, 0, 0);
        QVERIFY(throwsInvalidInput(keys));
        // Orientations are normalised.
        keys = someKeyframes();
        keys[0].orientation.coeffs() *= 3.0;
        QVERIFY(std::abs(KeyframedPath(keys).poseAt(0.0).orientation.norm() - 1.0) < 1e-15);
    }
};

AIRTRAP_TEST_APPLESS(TestKinematicMotion)
#include "TestKinematicMotion.moc"
