#pragma once
// Turns a bubble into the rigid body the solver couples to the water (paper §3.2): a sphere of
// the bubble's radius and density ratio × ρ₀, one layer of boundary particles half a spacing
// inside its surface (like every body, so the water's volume ends at the surface), frictionless
// against the water (eq. 6's drag acts on the whole bubble instead) and soft against other
// bodies.
#include "bubbles/BubbleState.h"
#include "rigid/RigidBody.h"
#include "scene/Scene.h"
#include "sph/CubicSplineKernel.h"

namespace airtrap {

class BubbleBodyFactory {
public:
    BubbleBodyFactory(const BubbleSettings& bubbles, const SolverSettings& solver,
                      const CubicSplineKernel& kernel);

    //! The body of `bubble`, in its cached state.
    RigidBody build(const BubbleState& bubble) const;
    //! kg, the mass of a bubble of `radius` m.
    double massOf(double radius) const;

private:
    double density_; //!< kg/m³
    double spacing_;
    CubicSplineKernel kernel_;
};

} // namespace airtrap
