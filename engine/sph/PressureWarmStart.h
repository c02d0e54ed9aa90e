#pragma once
// A divergence-free solver's stiffness values at the end of a step, per particle in the water's
// order, from which the next step's solves start (docs/METHOD.md "Water: divergence-free SPH").
// Part of the cached state, so that a resumed bake takes the same iterations as an unbroken one.
// Empty for WCSPH.
#include <vector>

namespace airtrap {

struct PressureWarmStart {
    //! q (m⁵/(kg·s)) of the divergence solve, summed over its iterations: the velocity change
    //! it made is −Σⱼ mⱼ(qᵢ + qⱼ)∇Wᵢⱼ.
    std::vector<float> divergence;
    //! κ = p/ρ² (m⁵/(kg·s²)) of the density solve: the pressure the water held, over ρ².
    std::vector<float> density;

    bool empty() const { return divergence.empty() && density.empty(); }
    bool operator==(const PressureWarmStart& other) const = default;
};

} // namespace airtrap
