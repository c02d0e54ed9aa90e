#pragma once
// The geometry and timing of an inflow nozzle (the paper's "pouring water"), apart from the
// particles it emits: the nozzle frame, the lattice of one layer, and when each layer leaves.
// Layer k leaves at t_k = start + k·Δx/speed, so everything here is a pure function of the
// scene. The validator and the command line count with it; sim/InflowEmitter emits with it.
#include "scene/Scene.h"

#include <cstddef>
#include <vector>

namespace airtrap {

class InflowNozzle {
public:
    //! `spacing` is the scene's particle spacing Δx.
    InflowNozzle(const InflowEmitterSettings& settings, double spacing);

    //! Particles in one layer: the Δx lattice of the nozzle plane clipped to the disc or rectangle.
    std::size_t particlesPerLayer() const { return offsets_.size(); }
    //! Whole layers the budget allows (max_particles / particlesPerLayer, rounded down).
    std::size_t layerBudget() const { return layerBudget_; }
    //! s, time at which layer `k` leaves the nozzle plane.
    double layerTime(std::size_t k) const;
    //! Layers that left the nozzle strictly before `time`: those with t_k < time, t_k < stop
    //! and k < layerBudget().
    std::size_t layersBefore(double time) const;

    //! Unit vectors of the nozzle frame: the jet direction, the width axis (horizontal, or x for
    //! a vertical jet) and the height axis.
    const Vec3d& direction() const { return direction_; }
    const Vec3d& widthAxis() const { return widthAxis_; }
    const Vec3d& heightAxis() const { return heightAxis_; }
    //! Lattice points of one layer, relative to the nozzle centre, m.
    const std::vector<Vec3d>& layerOffsets() const { return offsets_; }
    const InflowEmitterSettings& settings() const { return settings_; }
    double spacing() const { return spacing_; }

    //! Half-extents along x, y and z of the nozzle's exit plane (disc or rectangle), m.
    static Vec3d exitHalfExtent(const InflowEmitterSettings& settings);
    //! The width and height axes for a jet along `direction` (non-zero, any length).
    static void nozzleFrame(const Vec3d& direction, Vec3d& widthAxis, Vec3d& heightAxis);

private:
    InflowEmitterSettings settings_;
    double spacing_;
    Vec3d direction_;
    Vec3d widthAxis_;
    Vec3d heightAxis_;
    std::vector<Vec3d> offsets_;
    std::size_t layerBudget_ = 0;
};

} // namespace airtrap
