// The only translation unit of rigid/ that includes OpenVDB: its headers take long to compile.
#include "rigid/SignedDistanceField.h"

#include "core/Error.h"
#include "rigid/TriangleMesh.h"

#include <cmath>
#include <mutex>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/MeshToVolume.h>
#include <string>

namespace airtrap {

struct SignedDistanceField::Grid {
    openvdb::FloatGrid::Ptr grid;
    double voxelSize = 0.0;
};

namespace {

void initializeOpenVdbOnce() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

void requirePositive(double value, const char* what) {
    if (std::isnan(value) || value <= 0.0)
        throw Error(ErrorKind::InvalidInput, std::string("signed distance field: ") + what +
                                                 " must be a positive number, got " +
                                                 std::to_string(value));
}

openvdb::Vec3d toVdb(const Vec3d& v) {
    return {v.x(), v.y(), v.z()};
}
Vec3d fromVdb(const openvdb::Vec3d& v) {
    return {v.x(), v.y(), v.z()};
}

} // namespace

SignedDistanceField::SignedDistanceField(const TriangleMesh& mesh, double voxelSize,
                                         double exteriorBandVoxels, double interiorBandVoxels)
    : grid_(std::make_unique<Grid>()) {
    requirePositive(voxelSize, "voxel size");
    requirePositive(exteriorBandVoxels, "exterior band");
    requirePositive(interiorBandVoxels, "interior band");
    if (mesh.triangles.empty())
        throw Error(ErrorKind::InvalidInput, "signed distance field: the mesh has no triangles");
    if (!std::isfinite(exteriorBandVoxels))
        throw Error(ErrorKind::InvalidInput, "signed distance field: the exterior band must be "
                                             "finite (the outside is unbounded)");
    initializeOpenVdbOnce();

    std::vector<openvdb::Vec3s> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3d& v : mesh.vertices)
        points.emplace_back(float(v.x()), float(v.y()), float(v.z()));
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const TriangleMesh::Triangle& t : mesh.triangles)
        triangles.emplace_back(t[0], t[1], t[2]);

    // OpenVDB fills the whole interior with distances when the interior band is float's max;
    // otherwise it flood-fills the sign into the untouched interior, which keeps isInside right.
    const float interior = std::isfinite(interiorBandVoxels) ? float(interiorBandVoxels)
                                                             : std::numeric_limits<float>::max();
    const auto transform = openvdb::math::Transform::createLinearTransform(voxelSize);
    grid_->grid = openvdb::tools::meshToSignedDistanceField<openvdb::FloatGrid>(
        *transform, points, triangles, {}, float(exteriorBandVoxels), interior);
    grid_->grid->setName("surface");
    grid_->voxelSize = voxelSize;
}

SignedDistanceField::~SignedDistanceField() = default;
SignedDistanceField::SignedDistanceField(SignedDistanceField&&) noexcept = default;
SignedDistanceField& SignedDistanceField::operator=(SignedDistanceField&&) noexcept = default;

double SignedDistanceField::distance(const Vec3d& x) const {
    // One accessor per call: accessors cache tree paths and are not safe to share across threads,
    // while the tree itself is safe to read concurrently. The unregistered ("unsafe") kind skips
    // the tree's accessor registry, which only matters for trees that change: this one never
    // does after construction.
    const auto accessor = grid_->grid->getConstUnsafeAccessor();
    const openvdb::Vec3d indexPoint = grid_->grid->transform().worldToIndex(toVdb(x));
    return openvdb::tools::BoxSampler::sample(accessor, indexPoint);
}

Vec3d SignedDistanceField::normal(const Vec3d& x) const {
    const double h = grid_->voxelSize;
    Vec3d gradient;
    for (int axis = 0; axis < 3; ++axis) {
        const Vec3d step = Vec3d::Unit(axis) * h;
        gradient[axis] = distance(x + step) - distance(x - step);
    }
    const double length = gradient.norm();
    return length > 0.0 ? Vec3d(gradient / length) : Vec3d::Zero();
}

bool SignedDistanceField::isInside(const Vec3d& x) const {
    return distance(x) < 0.0;
}

Aabb SignedDistanceField::bounds() const {
    const openvdb::CoordBBox active = grid_->grid->evalActiveVoxelBoundingBox();
    const openvdb::BBoxd world = grid_->grid->transform().indexToWorld(active);
    return {fromVdb(world.min()), fromVdb(world.max())};
}

double SignedDistanceField::voxelSize() const {
    return grid_->voxelSize;
}

double SignedDistanceField::exteriorBand() const {
    return grid_->grid->background();
}

} // namespace airtrap
