#include "bubbles/BubbleBodyFactory.h"

#include "rigid/MassProperties.h"
#include "rigid/ShapeSampler.h"
#include "sph/BoundaryVolumes.h"

#include <algorithm>
#include <string>

namespace airtrap {

BubbleBodyFactory::BubbleBodyFactory(const BubbleSettings& bubbles, const SolverSettings& solver,
                                     const CubicSplineKernel& kernel)
    : density_(bubbles.densityRatio * solver.restDensity), spacing_(solver.particleSpacing),
      kernel_(kernel) {}

double BubbleBodyFactory::massOf(double radius) const {
    return MassProperties::ofSphere(radius, density_).mass;
}

RigidBody BubbleBodyFactory::build(const BubbleState& bubble) const {
    const double half = 0.5 * spacing_;
    // A bubble is at least a spacing in radius, so its layer keeps a sphere of half a spacing.
    BoundaryParticles layer =
        ShapeSampler::sampleSphere(std::max(bubble.radius - half, half), spacing_);
    BoundaryVolumes::compute(layer, kernel_, spacing_);
    RigidBody body("bubble " + std::to_string(bubble.id), std::move(layer),
                   BodyShape::sphere(bubble.radius),
                   RigidPose{bubble.body.position, bubble.body.orientation});
    body.setSurfaceOffset(half);
    // No bounce and no friction against the water: the slip between bubble and water is eq. 6's
    // drag. Against another body a pair takes the bouncier restitution (ContactMaterial), so a
    // bubble bounces off a bouncy body and is stopped by any other.
    body.setMaterials(ContactMaterial{0.0, 0.0}, ContactMaterial{0.0, 0.0});
    const MassProperties mass = MassProperties::ofSphere(bubble.radius, density_);
    body.makeDynamic(RigidBodyInertia(mass.mass, mass.inertia), mass.volume, Vec3d::Zero(), {});
    body.setState(bubble.body);
    return body;
}

} // namespace airtrap
