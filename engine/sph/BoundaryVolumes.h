#pragma once
// The volume each boundary particle stands in for in the water's sums (Akinci et al. 2012,
// docs/METHOD.md "Impulse-based boundary force"): a body's particles are sampled only roughly
// evenly, so each takes the volume its own body's sampling density gives it.
#include "rigid/BoundaryParticles.h"
#include "sph/CubicSplineKernel.h"

namespace airtrap {

class BoundaryVolumes {
public:
    //! Sets each particle's volume from the density of its own body's sampling (Akinci et al.
    //! 2012: V_b ∝ 1 / Σ_k W_bk, k over the body's particles including b), scaled so that a flat
    //! wall sampled at the water's spacing Δx has V_b = Δx³. Unscaled, 1/ΣW is about 1.4 Δx³ at a
    //! support of 2Δx: the wall would stand in for 40 % more water than it replaces and push the
    //! first layer off it. Scaled, a resting pool is in balance from the first step.
    static void compute(BoundaryParticles& particles, const CubicSplineKernel& kernel,
                        double spacing);

    //! Σ_k W(|x_k|) over an infinite flat square lattice of the given spacing, the point itself
    //! included: the reference density of a wall sampled at the water's spacing.
    static double flatLatticeKernelSum(const CubicSplineKernel& kernel, double spacing);
};

} // namespace airtrap
