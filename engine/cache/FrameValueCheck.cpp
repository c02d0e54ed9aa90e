#include "cache/FrameValueCheck.h"

#include "core/Error.h"

#include <cmath>
#include <sstream>

namespace airtrap {
namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& what) {
    throw Error(ErrorKind::CacheCorrupt, path + ": " + what);
}

std::string numberText(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

std::string pointText(const Vec3d& p) {
    std::ostringstream text;
    text << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return text.str();
}

void requireFinite(double value, const std::string& path, const std::string& what) {
    if (!std::isfinite(value))
        refuse(path, what + " is " + numberText(value) + ", expected a finite number");
}

template <class Vector>
void requireFinite(const Vector& v, const std::string& path, const std::string& what) {
    for (Eigen::Index k = 0; k < v.size(); ++k)
        requireFinite(double(v[k]), path, what + " (component " + std::to_string(k) + ")");
}

void checkBody(const RigidBodyState& body, const std::string& path, const std::string& which) {
    requireFinite(body.position, path, "the position of " + which);
    requireFinite(body.orientation.coeffs(), path, "the orientation of " + which);
    requireFinite(body.linearVelocity, path, "the velocity of " + which);
    requireFinite(body.angularVelocity, path, "the angular velocity of " + which);
}

void checkWater(const ParticleSet& fluid, const std::string& path) {
    for (std::size_t i = 0; i < fluid.size(); ++i) {
        const std::string which = " of particle " + std::to_string(i);
        requireFinite(fluid.positions[i], path, "attribute 'positions'" + which);
        requireFinite(fluid.velocities[i], path, "attribute 'velocities'" + which);
        requireFinite(double(fluid.densities[i]), path, "attribute 'densities'" + which);
    }
}

void checkWarmStart(const PressureWarmStart& warmStart, const std::string& path) {
    for (std::size_t i = 0; i < warmStart.divergence.size(); ++i)
        requireFinite(double(warmStart.divergence[i]), path,
                      "the divergence warm start of particle " + std::to_string(i));
    for (std::size_t i = 0; i < warmStart.density.size(); ++i)
        requireFinite(double(warmStart.density[i]), path,
                      "the density warm start of particle " + std::to_string(i));
}

} // namespace

void checkFrameValuesAreFinite(const FrameData& frame, const std::string& path) {
    const SimulationState& state = frame.state;
    requireFinite(state.time, path, "the frame's time");
    requireFinite(state.lastTimeStep, path, "the last time step");
    checkWater(state.fluid, path);
    for (std::size_t b = 0; b < state.bodies.size(); ++b)
        checkBody(state.bodies[b], path, "body " + std::to_string(b));
    for (const BubbleState& bubble : state.bubbles) {
        const std::string which = "bubble " + std::to_string(bubble.id);
        requireFinite(bubble.radius, path, "the radius of " + which);
        checkBody(bubble.body, path, which);
    }
    checkWarmStart(state.warmStart, path);
}

void checkFrameLiesInDomain(const FrameData& frame, const Aabb& domain, double margin,
                            const std::string& path) {
    const Aabb allowed = domain.expanded(margin);
    const std::string bounds = pointText(domain.min) + "–" + pointText(domain.max) +
                               " m (container plus headroom) with a margin of " +
                               numberText(margin) + " m";
    const std::vector<Vec3f>& positions = frame.state.fluid.positions;
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (const Vec3d p = positions[i].cast<double>(); !allowed.contains(p))
            refuse(path, "particle " + std::to_string(i) + " at " + pointText(p) +
                             " m lies outside the scene's domain, expected within " + bounds);
    for (const BubbleState& bubble : frame.state.bubbles)
        if (!allowed.contains(bubble.body.position))
            refuse(path, "bubble " + std::to_string(bubble.id) + " at " +
                             pointText(bubble.body.position) +
                             " m lies outside the scene's domain, expected within " + bounds);
}

} // namespace airtrap
