#include "sph/BodySolveCoupling.h"

#include "core/Parallel.h"

#include <algorithm>
#include <tbb/blocked_range.h>

namespace airtrap {
namespace {

using Range = tbb::blocked_range<std::size_t>;
constexpr std::size_t kGrain = 256;

//! The added mass of a sphere in unbounded ideal fluid is half the water it displaces (Lamb,
//! "Hydrodynamics", 1932, §92); compact bodies lie near it (a cube's is 0.6–0.7). It only sets
//! how far each iteration moves a body: a light body's velocity follows the water's response
//! without overshooting it, a heavy body's at once.
constexpr double kAddedMassShare = 0.5;
//! The least relaxation Aitken's update may choose.
constexpr double kLeastRelaxation = 0.01;

} // namespace

BodySolveCoupling::BodySolveCoupling(const CubicSplineKernel& kernel, float particleMass,
                                     float restDensity, float wallShare)
    : kernel_(kernel), particleMass_(particleMass), restDensity_(restDensity),
      wallShare_(wallShare) {}

void BodySolveCoupling::begin(const BoundaryModel& boundary, const PositionArrays& water,
                              const std::vector<float>& boundaryRate) {
    boundary_ = &boundary;
    water_ = &water;
    bodies_.clear();
    motionOf_.clear();
    nearWater_.clear();
    otherRate_.clear();
    holdsSinkingBody_ = false;
    const BoundaryLayer& layer = boundary.movingLayer();
    if (!boundary.hasDynamicBodies() || layer.size() == 0)
        return;
    for (std::uint32_t body : layer.bodyOf()) {
        if (body >= motionOf_.size())
            motionOf_.resize(body + 1, -1);
        const BodyContactTerms& terms = boundary.contactTerms(body);
        // Bubbles are too light and small for the iterate to settle within the few iterations a
        // solve takes: they move at their start velocity over the step, the one the water is
        // solved against here, and take the water's reaction afterwards (RigidCoupling, with
        // their added mass).
        if (motionOf_[body] >= 0 || !terms.dynamic || terms.bubble)
            continue;
        Motion motion;
        motion.body = body;
        motion.centre = terms.centre;
        motion.startVelocity = motion.velocity = terms.linearVelocity;
        motion.startSpin = motion.spin = terms.angularVelocity;
        motion.mass = 1.0 / terms.inverseMass;
        motion.inverseInertia = terms.inverseInertia;
        const double addedMass = kAddedMassShare * restDensity_ * terms.volume;
        motion.initialRelaxation = motion.mass / (motion.mass + addedMass);
        holdsSinkingBody_ = holdsSinkingBody_ || terms.sinksIn(restDensity_);
        motionOf_[body] = static_cast<std::int32_t>(bodies_.size());
        bodies_.push_back(motion);
    }
    for (std::uint32_t i : boundary.movingPairs().waterWithPartners()) {
        const float rate = dynamicRate(i);
        bool dynamicPartner = false;
        for (std::uint32_t b : boundary.movingPairs().boundaryNear(i))
            dynamicPartner = dynamicPartner || motionOf_[layer.bodyOf()[b]] >= 0;
        if (!dynamicPartner)
            continue;
        nearWater_.push_back(i);
        otherRate_.push_back(boundaryRate[i] - rate);
    }
    impulses_.assign(layer.size(), Vec3f::Zero());
    startSolve();
}

void BodySolveCoupling::startSolve() {
    for (Motion& motion : bodies_) {
        motion.relaxation = motion.spinRelaxation = motion.initialRelaxation;
        motion.hasResidual = false;
    }
}

double BodySolveCoupling::aitken(double relaxation, const Vec3d& previous, const Vec3d& current) {
    const Vec3d change = current - previous;
    const double change2 = change.squaredNorm();
    if (!(change2 > 0.0))
        return relaxation;
    // Bounded: a factor above 1 would extrapolate past the target, one near 0 would freeze the
    // body for the rest of the solve.
    return std::clamp(-relaxation * previous.dot(change) / change2, kLeastRelaxation, 1.0);
}

void BodySolveCoupling::update(const std::vector<float>& applied,
                               const std::vector<float>* alsoApplied, const Vec3d& drift,
                               std::vector<float>& boundaryRate) {
    if (!active())
        return;
    layerImpulses(applied, alsoApplied);
    const BoundaryLayer& layer = boundary_->movingLayer();
    std::vector<Vec3d> impulse(bodies_.size(), Vec3d::Zero());
    std::vector<Vec3d> angularImpulse(bodies_.size(), Vec3d::Zero());
    // In the layer's order: the same sums on any number of threads.
    for (std::size_t b = 0; b < layer.size(); ++b) {
        const std::int32_t k = motionOf_[layer.bodyOf()[b]];
        if (k < 0)
            continue;
        const Vec3d p = impulses_[b].cast<double>();
        impulse[k] += p;
        angularImpulse[k] += (layer.positions()[b].cast<double>() - bodies_[k].centre).cross(p);
    }
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
        Motion& motion = bodies_[k];
        const Vec3d residual =
            motion.startVelocity + impulse[k] / motion.mass + drift - motion.velocity;
        const Vec3d spinResidual =
            motion.startSpin + motion.inverseInertia * angularImpulse[k] - motion.spin;
        if (motion.hasResidual) {
            motion.relaxation = aitken(motion.relaxation, motion.residual, residual);
            motion.spinRelaxation =
                aitken(motion.spinRelaxation, motion.spinResidual, spinResidual);
        }
        motion.residual = residual;
        motion.spinResidual = spinResidual;
        motion.hasResidual = true;
        motion.velocity += motion.relaxation * residual;
        motion.spin += motion.spinRelaxation * spinResidual;
    }
    parallelFor(Range(0, nearWater_.size(), kGrain), [&](const Range& r) {
        for (std::size_t n = r.begin(); n != r.end(); ++n)
            boundaryRate[nearWater_[n]] = otherRate_[n] + dynamicRate(nearWater_[n]);
    });
}

void BodySolveCoupling::layerImpulses(const std::vector<float>& applied,
                                      const std::vector<float>* alsoApplied) {
    const BoundaryLayer& layer = boundary_->movingLayer();
    const float radius2 = kernel_.supportRadius() * kernel_.supportRadius();
    parallelFor(Range(0, layer.size(), kGrain), [&](const Range& r) {
        for (std::size_t b = r.begin(); b != r.end(); ++b) {
            if (motionOf_[layer.bodyOf()[b]] < 0)
                continue;
            const Vec3f xb = layer.positions()[b];
            Vec3f sum = Vec3f::Zero();
            for (std::uint32_t i : boundary_->movingPairs().waterNear(b)) {
                const Vec3f d = (*water_)[i] - xb;
                const float r2 = d.squaredNorm();
                if (r2 >= radius2)
                    continue;
                const float stiffness = applied[i] + (alsoApplied ? (*alsoApplied)[i] : 0.0f);
                sum += stiffness * kernel_.gradientFromSquared(d, r2);
            }
            // The water particle's velocity changed by −(share) qᵢ Ψ_b ∇W_ib: the body takes the
            // opposite momentum.
            impulses_[b] = (wallShare_ * particleMass_ * layer.psi()[b]) * sum;
        }
    });
}

float BodySolveCoupling::dynamicRate(std::size_t i) const {
    const BoundaryLayer& layer = boundary_->movingLayer();
    const float radius2 = kernel_.supportRadius() * kernel_.supportRadius();
    const Vec3f xi = (*water_)[i];
    float rate = 0.0f;
    for (std::uint32_t b : boundary_->movingPairs().boundaryNear(i)) {
        if (motionOf_[layer.bodyOf()[b]] < 0)
            continue;
        const Vec3f d = xi - layer.positions()[b];
        const float r2 = d.squaredNorm();
        if (r2 < radius2)
            rate += layer.psi()[b] * layerVelocity(b).dot(kernel_.gradientFromSquared(d, r2));
    }
    return rate;
}

Vec3f BodySolveCoupling::layerVelocity(std::uint32_t b) const {
    const BoundaryLayer& layer = boundary_->movingLayer();
    const Motion& motion = bodies_[motionOf_[layer.bodyOf()[b]]];
    const Vec3d arm = layer.positions()[b].cast<double>() - motion.centre;
    return (motion.velocity + motion.spin.cross(arm)).cast<float>();
}

std::size_t BodySolveCoupling::allocatedBytes() const {
    return bodies_.capacity() * sizeof(Motion) + motionOf_.capacity() * sizeof(std::int32_t) +
           nearWater_.capacity() * sizeof(std::uint32_t) + otherRate_.capacity() * sizeof(float) +
           impulses_.capacity() * sizeof(Vec3f);
}

} // namespace airtrap
