#pragma once
#include "rigid/BoundaryParticles.h"
#include "sph/CubicSplineKernel.h"

namespace airtrap {

//! Places boundary particles on body surfaces and gives each its volume.
class BoundarySampler {
public:
    //! Which side of a box the water is on.
    enum class WaterSide { Inside, Outside };

    //! Samples the faces of `box` on a lattice of about `spacing`; the top face (+y) is left out
    //! when `openTop` is set. Normals point to `side`; at edges and corners they are the
    //! normalised sum of the faces' normals.
    static BoundaryParticles sampleBox(const Aabb& box, double spacing, WaterSide side,
                                       bool openTop);

    //! Sets each particle's volume from the density of its own body's sampling (Akinci et al.
    //! 2012: V_b ∝ 1 / Σ_k W_bk, k over the body's particles including b), scaled so that a flat
    //! wall sampled at the water's spacing Δx has V_b = Δx³. Unscaled, 1/ΣW is about 1.4 Δx³ at a
    //! support of 2Δx: the wall would stand in for 40 % more water than it replaces and push the
    //! first layer off it. Scaled, a resting pool is in balance from the first step.
    static void computeVolumes(BoundaryParticles& particles, const CubicSplineKernel& kernel,
                               double spacing);

    //! Σ_k W(|x_k|) over an infinite flat square lattice of the given spacing, the point itself
    //! included: the reference density of a wall sampled at the water's spacing.
    static double flatLatticeKernelSum(const CubicSplineKernel& kernel, double spacing);
};

} // namespace airtrap
