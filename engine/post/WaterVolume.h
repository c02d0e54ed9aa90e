#pragma once
// The water of one frame as a narrow-band level set (OpenVDB), the source of the free-surface
// mesh and of the VDB export. Built the way a renderer's particle surfacer does it: a sphere per
// particle, unioned, then smoothed by mean-curvature flow. Smoothing alone would shrink the
// water, so the level set is then moved along its normals until it encloses the particles'
// volume again (N particles × spacing³: each particle stands for one lattice cell of water).
#include "core/Interrupter.h"
#include "core/Math.h"
#include "rigid/TriangleMesh.h"
#include "scene/Scene.h"
#include "sph/ParticleSet.h"

#include <memory>
#include <optional>

namespace airtrap {

struct WaterGrids;

class WaterVolume {
public:
    //! The level set of `fluid` (particles placed `spacing` apart at t = 0); with no particles,
    //! empty grids of the right voxel size. Returns a volume without grids when stopped through
    //! `interrupter`. Throws Error(InvalidInput) for settings out of range.
    static WaterVolume build(const ParticleSet& fluid, double spacing,
                             const SurfaceMeshSettings& settings,
                             Interrupter* interrupter = nullptr);
    //! The same, for water held inside `walls` (the tank with its headroom): the surface meets
    //! each wall square on and ends in its plane, instead of rounding off one to two spacings
    //! short of it, so that a renderer sees no gap between water and glass. Particles near a
    //! wall are mirrored across it for the surface, which is then cut to the box.
    static WaterVolume build(const ParticleSet& fluid, double spacing,
                             const SurfaceMeshSettings& settings, const std::optional<Aabb>& walls,
                             Interrupter* interrupter = nullptr);

    WaterVolume() = default;
    //! Adopts grids read back from a file (WaterVolumeFile::read).
    WaterVolume(std::shared_ptr<const WaterGrids> grids, double particleVolume);

    //! No water: nothing built yet, stopped while building, or no particles.
    bool empty() const;
    double voxelSize() const;
    //! m³ inside the zero level set.
    double volume() const;
    //! m³ the particles stand for: the volume the level set was matched to.
    double particleVolume() const { return particleVolume_; }
    //! Distance to the surface at `x`, m: negative inside the water, clamped to the narrow band.
    double signedDistance(const Vec3d& x) const;
    //! Velocity of the particle nearest to `x`, m/s, within the surface's narrow band; zero
    //! elsewhere (a renderer's motion blur reads it at the surface only).
    Vec3d velocity(const Vec3d& x) const;
    //! The zero level set as a closed mesh, counter-clockwise seen from outside the water.
    TriangleMesh mesh() const;

    //! The OpenVDB grids, for exporters (post/WaterGrids.h); null when stopped while building.
    const WaterGrids* grids() const { return grids_.get(); }

private:
    std::shared_ptr<const WaterGrids> grids_;
    double particleVolume_ = 0.0;
};

} // namespace airtrap
