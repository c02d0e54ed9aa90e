#pragma once
// Signed distance to a mesh body's surface on a sparse voxel grid (OpenVDB), in the body's frame:
// contact normals, inside tests and surface checks for mesh shapes (docs/METHOD.md "Contacts
// between bodies"). OpenVDB stays in the .cpp: its headers cost a minute of compile time each.
#include "core/Math.h"

#include <limits>
#include <memory>

namespace airtrap {

struct TriangleMesh;

class SignedDistanceField {
public:
    //! Voxelises a closed, outward-facing `mesh` with cubic voxels of `voxelSize` (m).
    //! `exteriorBandVoxels` of true distance are kept outside the surface; inside, the whole
    //! interior holds true distances by default (memory grows with the solid's volume in voxels:
    //! a 1 m cube at 1 cm is 10⁶ voxels, 4 MB). A finite `interiorBandVoxels` keeps memory to the
    //! surface's neighbourhood; deeper points then read −(that band) but stay inside.
    //! @throw Error (InvalidInput) for a non-positive voxel size or band, or an empty mesh.
    SignedDistanceField(const TriangleMesh& mesh, double voxelSize, double exteriorBandVoxels = 3.0,
                        double interiorBandVoxels = std::numeric_limits<double>::infinity());
    ~SignedDistanceField();
    SignedDistanceField(SignedDistanceField&&) noexcept;
    SignedDistanceField& operator=(SignedDistanceField&&) noexcept;

    //! Signed distance to the surface at body-local `x`, m: negative inside. Trilinear between
    //! voxel centres; beyond the exterior band it is the band's width, exteriorBand().
    double distance(const Vec3d& x) const;
    //! Outward unit normal at `x`: the normalised gradient of the distance (central differences
    //! one voxel apart). Zero where the field is flat, far outside the band.
    Vec3d normal(const Vec3d& x) const;
    //! Whether `x` lies inside the solid, however deep.
    bool isInside(const Vec3d& x) const;
    //! Box around the voxels that hold distances (the surface plus its bands), m.
    Aabb bounds() const;

    double voxelSize() const;    //!< m
    double exteriorBand() const; //!< m, the distance reported far outside

private:
    struct Grid; // the OpenVDB grid, out of sight of every other translation unit
    std::unique_ptr<Grid> grid_;
};

} // namespace airtrap
