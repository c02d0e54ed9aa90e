// The water's level set (paper §4.1): built from particles on the lattice a scene starts from, it
// must enclose the water those particles stand for and put its surface on the water's faces, as a
// closed mesh facing outward.
#include "core/Error.h"
#include "post/WaterVolume.h"
#include "support/TestMain.h"
#include "unit/SceneTestSupport.h"

#include <QtTest>
#include <cmath>

using namespace airtrap;

namespace {

//! Particles at the centres of the `spacing` lattice cells filling `box`, as a fluid block is
//! filled, so the block's volume is exactly count × spacing³.
ParticleSet latticeBlock(const Aabb& box, double spacing) {
    ParticleSet fluid;
    const Vec3i cells = (box.size() / spacing).array().round().cast<int>();
    std::uint32_t id = 0;
    for (int i = 0; i < cells.x(); ++i)
        for (int j = 0; j < cells.y(); ++j)
            for (int k = 0; k < cells.z(); ++k) {
                const Vec3d p = box.min + spacing * Vec3d(i + 0.5, j + 0.5, k + 0.5);
                fluid.push(p.cast<float>(), Vec3f::Zero(), 1000.0f, id++);
            }
    return fluid;
}

//! The lattice cells whose centres lie inside the ball.
ParticleSet latticeBall(const Vec3d& centre, double radius, double spacing) {
    ParticleSet fluid;
    const Aabb box{centre - Vec3d::Constant(radius), centre + Vec3d::Constant(radius)};
    const ParticleSet cube = latticeBlock(box, spacing);
    for (std::size_t n = 0; n < cube.size(); ++n)
        if ((cube.positions[n].cast<double>() - centre).norm() < radius)
            fluid.push(cube.positions[n], Vec3f::Zero(), 1000.0f, cube.ids[n]);
    return fluid;
}

} // namespace

class TestWaterVolume : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void aRestingBlockEnclosesItsWaterVolume() {
        const double spacing = 0.02;
        const Aabb block{Vec3d(0.1, 0.0, 0.2), Vec3d(0.6, 0.3, 0.6)};
        const WaterVolume water = WaterVolume::build(latticeBlock(block, spacing), spacing, {});
        QVERIFY(!water.empty());
        QCOMPARE(water.voxelSize(), 0.5 * spacing);
        QVERIFY(std::abs(water.particleVolume() / block.volume() - 1.0) < 1e-9);

        const TriangleMesh mesh = water.mesh();
        const TriangleMesh::EdgeCounts edges = mesh.countEdges();
        QCOMPARE(edges.open, std::size_t(0));
        QCOMPARE(edges.misoriented, std::size_t(0));
        // docs/VALIDATION.md "Water surface": the mesh of a resting pool encloses its water
        // volume within 3 %.
        const double error = mesh.signedVolume() / block.volume() - 1.0;
        QVERIFY2(std::abs(error) < 0.03, qPrintable(QString("volume error %1").arg(error)));
    }

    void theSurfaceLiesOnTheBlocksFaces() {
        const double spacing = 0.02;
        const Aabb block{Vec3d(0.1, 0.0, 0.2), Vec3d(0.6, 0.3, 0.6)};
        const WaterVolume water = WaterVolume::build(latticeBlock(block, spacing), spacing, {});
        const Vec3d middle = block.center();
        // Mid-face, away from the rounded edges, the surface sits on the face to a tenth of a
        // spacing: the lattice's particles stand half a spacing inside it.
        const std::vector<Vec3d> faces = {{middle.x(), block.max.y(), middle.z()},
                                          {block.min.x(), middle.y(), middle.z()},
                                          {block.max.x(), middle.y(), middle.z()},
                                          {middle.x(), middle.y(), block.min.z()},
                                          {middle.x(), block.min.y(), middle.z()}};
        for (const Vec3d& face : faces) {
            const double distance = water.signedDistance(face);
            QVERIFY2(std::abs(distance) < 0.1 * spacing,
                     qPrintable(QString("off the face by %1 m").arg(distance)));
        }
        QVERIFY(water.signedDistance(middle) < 0.0);
        QVERIFY(water.signedDistance(block.max + Vec3d::Constant(0.1)) > 0.0);
    }

    void aBallOfWaterIsAClosedOutwardMeshOfItsVolume() {
        const double spacing = 0.01;
        const Vec3d centre(0.3, 0.4, 0.5);
        const ParticleSet ball = latticeBall(centre, 0.1, spacing);
        const WaterVolume water = WaterVolume::build(ball, spacing, {});
        const TriangleMesh mesh = water.mesh();
        QVERIFY(mesh.signedVolume() > 0.0);
        QCOMPARE(mesh.countEdges().open, std::size_t(0));
        const double error = mesh.signedVolume() / water.particleVolume() - 1.0;
        QVERIFY2(std::abs(error) < 0.03, qPrintable(QString("volume error %1").arg(error)));
        // Smoothing rounds the lattice's steps into the sphere of that volume.
        const double radius = std::cbrt(3.0 * water.particleVolume() / (4.0 * kPi));
        for (const Vec3d& v : mesh.vertices)
            QVERIFY2(std::abs((v - centre).norm() - radius) < 0.5 * spacing,
                     qPrintable(QString("vertex %1 m from the centre, radius %2 m")
                                    .arg((v - centre).norm())
                                    .arg(radius)));
    }

    void noWaterGivesAnEmptyVolume() {
        const WaterVolume water = WaterVolume::build(ParticleSet(), 0.02, {});
        QVERIFY(water.empty());
        QCOMPARE(water.mesh().triangleCount(), std::size_t(0));
        QCOMPARE(water.volume(), 0.0);
    }

    void settingsOutOfRangeAreRefused() {
        const ParticleSet fluid = latticeBlock({Vec3d::Zero(), Vec3d::Constant(0.1)}, 0.02);
        SurfaceMeshSettings coarse;
        coarse.voxelSize = 1.0; // the spheres (1 spacing) would be narrower than 1.5 voxels
        QVERIFY_THROWS_EXCEPTION(Error, WaterVolume::build(fluid, 0.02, coarse));
        SurfaceMeshSettings rough;
        rough.smoothing = -1;
        QVERIFY_THROWS_EXCEPTION(Error, WaterVolume::build(fluid, 0.02, rough));
        QVERIFY_THROWS_EXCEPTION(Error, WaterVolume::build(fluid, 0.0, {}));
        // Worded as the scene validator words them, from the same declarations and rule.
        const std::string tooCoarse = test::errorMessage(
            [&] { WaterVolume::build(fluid, 0.02, coarse); }, ErrorKind::InvalidInput);
        QVERIFY2(test::contains(tooCoarse, "surface_mesh.particle_radius = 1 is less than 1.5 × "
                                           "surface_mesh.voxel_size"),
                 tooCoarse.c_str());
        const std::string tooRough = test::errorMessage(
            [&] { WaterVolume::build(fluid, 0.02, rough); }, ErrorKind::InvalidInput);
        QVERIFY2(test::contains(tooRough, "surface_mesh.smoothing = -1 is out of range"),
                 tooRough.c_str());
    }
};

AIRTRAP_TEST_APPLESS(TestWaterVolume)
#include "TestWaterVolume.moc"
