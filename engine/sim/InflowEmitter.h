#pragma once
// The inflow nozzle of the paper's "pouring water" scenes. Emission is a pure function of the
// simulated time: layer k leaves the nozzle at t_k = start + k·Δx/speed, so the particles present
// at any time follow from the scene alone and a resumed bake emits exactly what a straight one
// does, with no emitter state in the cache.
#include "scene/Scene.h"
#include "sim/SimulationState.h"

#include <cstddef>
#include <vector>

namespace airtrap {

class InflowEmitter {
public:
    //! `spacing` is the scene's particle spacing Δx; emitted particles get `restDensity`.
    InflowEmitter(const InflowEmitterSettings& settings, double spacing, double restDensity);

    //! Particles in one layer: the Δx lattice of the nozzle plane clipped to the disc or rectangle.
    std::size_t particlesPerLayer() const { return offsets_.size(); }
    //! Whole layers the budget allows (max_particles / particlesPerLayer, rounded down).
    std::size_t layerBudget() const { return layerBudget_; }
    //! s, time at which layer `k` leaves the nozzle plane.
    double layerTime(std::size_t k) const;
    //! Layers that left the nozzle strictly before `time`: those with t_k < time, t_k < stop
    //! and k < layerBudget().
    std::size_t layersBefore(double time) const;

    //! Appends the layers that leave during [from, to), each where it is at `to`: the nozzle plane
    //! advanced by speed·(to − t_k) along the direction, so consecutive layers are Δx apart.
    //! Ids come from state.nextParticleId. Returns the number of particles added.
    std::size_t emit(double from, double to, SimulationState& state) const;

    //! Unit vectors of the nozzle frame: the jet direction, the width axis (horizontal, or x for
    //! a vertical jet) and the height axis.
    const Vec3d& direction() const { return direction_; }
    const Vec3d& widthAxis() const { return widthAxis_; }
    const Vec3d& heightAxis() const { return heightAxis_; }

    //! The width and height axes for a jet along `direction` (non-zero, any length).
    static void nozzleFrame(const Vec3d& direction, Vec3d& widthAxis, Vec3d& heightAxis);

private:
    InflowEmitterSettings settings_;
    double spacing_;
    float restDensity_;
    Vec3d direction_;
    Vec3d widthAxis_;
    Vec3d heightAxis_;
    std::vector<Vec3d> offsets_; //!< lattice points of one layer, relative to the nozzle centre
    std::size_t layerBudget_ = 0;
};

} // namespace airtrap
