// One of the few translation units that include OpenVDB's tools: their headers take long to
// compile, so they stay out of headers and out of most .cpp files.
#include "post/WaterVolume.h"

#include "core/Error.h"
#include "post/WaterGrids.h"
#include "scene/SceneSchema.h"
#include "scene/SceneValidator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/LevelSetRebuild.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <string>

namespace airtrap {

namespace {

void initialiseOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

//! The particle list OpenVDB's ParticlesToLevelSet reads: every sphere the same size, each
//! carrying its velocity into the voxels it is nearest to.
class ParticleList {
public:
    using PosType = openvdb::Vec3R;

    explicit ParticleList(const ParticleSet& fluid) : fluid_(fluid) {}
    std::size_t size() const { return fluid_.size(); }
    void getPos(std::size_t n, openvdb::Vec3R& xyz) const {
        const Vec3f& p = fluid_.positions[n];
        xyz = openvdb::Vec3R(p.x(), p.y(), p.z());
    }
    void getAtt(std::size_t n, openvdb::Vec3s& velocity) const {
        const Vec3f& v = fluid_.velocities[n];
        velocity = openvdb::Vec3s(v.x(), v.y(), v.z());
    }

private:
    const ParticleSet& fluid_;
};

//! The scene validator refuses these before a bake; a caller with its own settings (a test, a
//! tool) gets the same rules here, from the same declarations, worded with the scene's keys.
void checkSettings(double spacing, const SurfaceMeshSettings& settings) {
    Scene scene;
    scene.solver.particleSpacing = spacing;
    scene.surfaceMesh = settings;
    for (const std::string& problem :
         {SceneSchema::check(scene, &SolverSettings::particleSpacing),
          SceneSchema::check(scene, &SurfaceMeshSettings::voxelSize),
          SceneSchema::check(scene, &SurfaceMeshSettings::particleRadius),
          SceneSchema::check(scene, &SurfaceMeshSettings::smoothing),
          SceneValidator::surfaceMeshRule(settings)})
        if (!problem.empty())
            throw Error(ErrorKind::InvalidInput, "free-surface mesh: " + problem);
}

using SurfaceFilter = openvdb::tools::LevelSetFilter<openvdb::FloatGrid>;

//! Moves the surface along its normals until it encloses `target` m³. One move by
//! (volume − target) / area is exact for a flat surface; the few passes absorb curvature. A move
//! is capped at `maxShift`, so a frame of mostly spray is not eroded away.
void matchVolume(SurfaceFilter& filter, double target, double maxShift) {
    constexpr int kPasses = 3;
    const double tolerance = 1e-4 * target;
    for (int pass = 0; pass < kPasses; ++pass) {
        const openvdb::FloatGrid& grid = filter.grid();
        const double volume = openvdb::tools::levelSetVolume(grid);
        const double area = openvdb::tools::levelSetArea(grid);
        if (!(area > 0.0) || std::abs(volume - target) <= tolerance)
            return;
        const double shift = std::clamp((volume - target) / area, -maxShift, maxShift);
        filter.offset(float(shift)); // positive offsets move the surface inward
    }
}

bool stopRequested(const Interrupter* interrupter) {
    return interrupter != nullptr && interrupter->stopRequested();
}

Vec3d toVec3d(const openvdb::Vec3s& p) {
    return {double(p.x()), double(p.y()), double(p.z())};
}

//! The union of one sphere of `radius` per particle as a signed distance in `grids.surface`, and
//! the nearest particle's velocity over its band in `grids.velocity`.
void rasterise(const ParticleSet& fluid, double radius, float halfWidth, WaterGrids& grids) {
    openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid, openvdb::Vec3s> raster(*grids.surface);
    raster.rasterizeSpheres(ParticleList(fluid), radius);
    raster.finalize(true);
    grids.velocity = raster.attributeGrid();
    // Inside the union of spheres the values only reach −radius; rebuilt, the grid is a true
    // signed distance with interior tiles, as the filters, the fog and renderers need.
    grids.surface = openvdb::tools::levelSetRebuild(*grids.surface, 0.0f, halfWidth);
    grids.surface->setName("surface");
}

//! Flattens the spheres' bumps, then gives back the volume the smoothing took.
void smoothKeepingVolume(openvdb::FloatGrid& surface, int passes, double volume, double maxShift) {
    SurfaceFilter filter(surface);
    // One renormalisation sweep per filter pass instead of three: the passes are small moves,
    // and the sweeps were two thirds of the stage's time.
    filter.setNormCount(1);
    for (int pass = 0; pass < passes; ++pass)
        filter.meanCurvature();
    matchVolume(filter, volume, maxShift);
}

//! `fluid` and, for every particle within `reach` of a wall of `walls`, its mirror image across
//! that wall (and, near an edge or a corner, across each pair and all three of the near walls).
//! The sphere union then continues through the walls as it would past a mirror: the surface meets
//! a wall square on, where alone it rounds off one to two spacings short of it.
ParticleSet withMirrorImages(const ParticleSet& fluid, const Aabb& walls, double reach) {
    ParticleSet all = fluid;
    for (std::size_t n = 0; n < fluid.size(); ++n) {
        const Vec3f& p = fluid.positions[n];
        // Per axis, the plane the particle is near (if any): images are every non-empty subset.
        std::array<std::optional<float>, 3> plane;
        for (int axis = 0; axis < 3; ++axis) {
            if (double(p[axis]) - walls.min[axis] < reach)
                plane[axis] = float(walls.min[axis]);
            else if (walls.max[axis] - double(p[axis]) < reach)
                plane[axis] = float(walls.max[axis]);
        }
        for (int subset = 1; subset < 8; ++subset) {
            Vec3f image = p;
            Vec3f velocity = fluid.velocities[n];
            bool exists = true;
            for (int axis = 0; axis < 3 && exists; ++axis) {
                if ((subset & (1 << axis)) == 0)
                    continue;
                exists = plane[axis].has_value();
                if (exists) {
                    image[axis] = 2.0f * *plane[axis] - p[axis];
                    velocity[axis] = -velocity[axis];
                }
            }
            if (exists)
                all.push(image, velocity, fluid.densities[n], fluid.ids[n]);
        }
    }
    return all;
}

//! Keeps the part of `surface` inside `walls`: the water's faces against them lie in their planes.
void clipToWalls(openvdb::FloatGrid& surface, const Aabb& walls, float halfWidth) {
    const openvdb::math::BBox<openvdb::Vec3d> box(
        openvdb::Vec3d(walls.min.x(), walls.min.y(), walls.min.z()),
        openvdb::Vec3d(walls.max.x(), walls.max.y(), walls.max.z()));
    openvdb::FloatGrid::Ptr inside =
        openvdb::tools::createLevelSetBox<openvdb::FloatGrid>(box, surface.transform(), halfWidth);
    openvdb::tools::csgIntersection(surface, *inside);
}

} // namespace

WaterVolume WaterVolume::build(const ParticleSet& fluid, double spacing,
                               const SurfaceMeshSettings& settings, Interrupter* interrupter) {
    return build(fluid, spacing, settings, std::nullopt, interrupter);
}

WaterVolume WaterVolume::build(const ParticleSet& fluid, double spacing,
                               const SurfaceMeshSettings& settings,
                               const std::optional<Aabb>& walls, Interrupter* interrupter) {
    checkSettings(spacing, settings);
    initialiseOpenVdb();
    const double voxel = settings.voxelSize * spacing;
    const double radius = settings.particleRadius * spacing;
    // Three voxels each side hold the filters' stencils; a wider band only costs time, as the
    // tracker rebuilds it after every move anyway.
    const float halfWidth = 3.0f;
    auto grids = std::make_shared<WaterGrids>();
    grids->surface = openvdb::createLevelSet<openvdb::FloatGrid>(voxel, halfWidth);
    grids->surface->setName("surface");
    grids->velocity = openvdb::Vec3SGrid::create();
    const double cell = spacing * spacing * spacing;
    const double particleVolume = double(fluid.size()) * cell;
    if (!fluid.empty()) {
        // Only an image whose sphere reaches into the tank shapes the surface there; a voxel more
        // keeps the smoothing's stencil at the wall symmetric.
        const ParticleSet rasterised =
            walls ? withMirrorImages(fluid, *walls, radius + voxel) : fluid;
        // OpenVDB's tools are not handed the interrupter: an interrupted tool cancels the TBB
        // task group it runs in, and when that is a caller's parallel loop (post makes frames
        // side by side) it cancels the other frames' tools halfway, whose half-built trees then
        // crashed the process. The stop is checked between the stages instead.
        rasterise(rasterised, radius, halfWidth, *grids);
        if (stopRequested(interrupter))
            return {};
        // The images are water too until the clip: their volume is matched with the rest.
        smoothKeepingVolume(*grids->surface, settings.smoothing, double(rasterised.size()) * cell,
                            radius);
        if (walls)
            clipToWalls(*grids->surface, *walls, halfWidth);
    }
    if (stopRequested(interrupter))
        return {};
    grids->velocity->setName("vel");
    grids->velocity->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);
    grids->velocity->setTransform(grids->surface->transform().copy());
    return WaterVolume(std::move(grids), particleVolume);
}

WaterVolume::WaterVolume(std::shared_ptr<const WaterGrids> grids, double particleVolume)
    : grids_(std::move(grids)), particleVolume_(particleVolume) {}

Vec3d WaterVolume::velocity(const Vec3d& x) const {
    if (empty() || !grids_->velocity)
        return Vec3d::Zero();
    const openvdb::Vec3SGrid& grid = *grids_->velocity;
    const openvdb::Vec3d index = grid.transform().worldToIndex(openvdb::Vec3d(x.x(), x.y(), x.z()));
    const openvdb::Vec3s v = openvdb::tools::PointSampler::sample(grid.tree(), index);
    return {v.x(), v.y(), v.z()};
}

bool WaterVolume::empty() const {
    return grids_ == nullptr || grids_->surface->tree().activeVoxelCount() == 0;
}

double WaterVolume::voxelSize() const {
    return grids_ == nullptr ? 0.0 : grids_->surface->voxelSize().x();
}

double WaterVolume::volume() const {
    return empty() ? 0.0 : openvdb::tools::levelSetVolume(*grids_->surface);
}

double WaterVolume::signedDistance(const Vec3d& x) const {
    if (empty())
        return std::numeric_limits<double>::infinity();
    const openvdb::FloatGrid& grid = *grids_->surface;
    const openvdb::Vec3d index = grid.transform().worldToIndex(openvdb::Vec3d(x.x(), x.y(), x.z()));
    return openvdb::tools::BoxSampler::sample(grid.tree(), index);
}

TriangleMesh WaterVolume::mesh() const {
    TriangleMesh mesh;
    if (empty())
        return mesh;
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*grids_->surface, points, triangles, quads, 0.0, 0.0);
    mesh.vertices.reserve(points.size());
    for (const openvdb::Vec3s& p : points)
        mesh.vertices.push_back(toVec3d(p));
    mesh.triangles.reserve(triangles.size() + 2 * quads.size());
    // OpenVDB winds its polygons clockwise seen from outside; ours are counter-clockwise.
    for (const openvdb::Vec3I& t : triangles)
        mesh.triangles.push_back({t[2], t[1], t[0]});
    for (const openvdb::Vec4I& q : quads) {
        mesh.triangles.push_back({q[2], q[1], q[0]});
        mesh.triangles.push_back({q[3], q[2], q[0]});
    }
    return mesh;
}

} // namespace airtrap
