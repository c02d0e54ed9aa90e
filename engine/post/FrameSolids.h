#pragma once
// The solids and bubbles of one cached frame, placed: what the free-surface mesh keeps its
// distance from (paper §4.1) and what the bodies export draws.
#include "post/NamedMesh.h"
#include "post/SceneSolids.h"

#include <vector>

namespace airtrap {

class FrameSolids {
public:
    //! Keeps a reference to `solids`, which must outlive this object.
    FrameSolids(const SceneSolids& solids, const SimulationState& state);

    //! Distance from `x` to the nearest surface of a solid or a bubble, m; negative inside one.
    double clearance(const Vec3d& x) const;
    //! The obstacles and bodies in world space, in scene order (not the tank).
    std::vector<NamedMesh> meshes() const;

private:
    struct PlacedSolid {
        const SceneSolids::Solid* solid;
        RigidPose pose;
    };
    struct Sphere {
        Vec3d centre;
        double radius;
    };

    std::vector<PlacedSolid> placed_;
    std::vector<Sphere> bubbles_;
};

} // namespace airtrap
