// The free-surface-only water mesh (paper §4.1, Fig. 2b/d): a resting pool in its tank, with a
// bubble and a sphere body floating in its surface, keeps its free surface at the water's height
// and loses every polygon within the margin of the tank, the bubble and the body. The solids are
// placed from the frame's state; the primitives exported for them are closed and face outward.
#include "post/FrameSolids.h"
#include "post/FreeSurface.h"
#include "post/SceneSolids.h"
#include "post/ShapeTessellation.h"
#include "post/WaterVolume.h"
#include "support/TestMain.h"

#include <QtTest>
#include <cmath>
#include <map>

using namespace airtrap;

namespace {

constexpr double kSpacing = 0.02;
constexpr double kDepth = 0.3;
const Vec3d kBubbleCentre(0.5, kDepth, 0.5);
constexpr double kBubbleRadius = 0.06;
const Vec3d kBallCentre(0.25, kDepth, 0.7);
constexpr double kBallRadius = 0.08;

Scene poolScene() {
    Scene scene;
    scene.solver.particleSpacing = kSpacing;
    RigidBodySettings ball;
    ball.name = "Ball";
    ball.shape = "sphere";
    ball.motion = "dynamic";
    ball.radius = kBallRadius;
    ball.position = kBallCentre;
    scene.bodies.push_back(ball);
    return scene;
}

//! The tank's unit floor filled to kDepth on the lattice, except where the bubble and the ball
//! are (and half a spacing around them, where their boundary particles keep the water off).
SimulationState poolState() {
    SimulationState state;
    std::uint32_t id = 0;
    const int columns = int(std::round(1.0 / kSpacing));
    const int rows = int(std::round(kDepth / kSpacing));
    for (int i = 0; i < columns; ++i)
        for (int j = 0; j < rows; ++j)
            for (int k = 0; k < columns; ++k) {
                const Vec3d p = kSpacing * Vec3d(i + 0.5, j + 0.5, k + 0.5);
                if ((p - kBubbleCentre).norm() < kBubbleRadius + 0.5 * kSpacing ||
                    (p - kBallCentre).norm() < kBallRadius + 0.5 * kSpacing)
                    continue;
                state.fluid.push(p.cast<float>(), Vec3f::Zero(), 1000.0f, id++);
            }
    BubbleState bubble;
    bubble.radius = kBubbleRadius;
    bubble.body.position = kBubbleCentre;
    state.bubbles.push_back(bubble);
    RigidBodyState ball;
    ball.position = kBallCentre;
    state.bodies.push_back(ball);
    return state;
}

//! Distance to the nearest of the tank's floor and walls, the bubble and the ball, worked out
//! here from the set-up rather than by the code under test.
double distanceToSolids(const Vec3d& x) {
    const double tank = std::min({x.y(), x.x(), 1.0 - x.x(), x.z(), 1.0 - x.z()});
    const double bubble = (x - kBubbleCentre).norm() - kBubbleRadius;
    const double ball = (x - kBallCentre).norm() - kBallRadius;
    return std::min({tank, bubble, ball});
}

//! The way into the nearest solid from `x`, by central differences of distanceToSolids().
Vec3d intoSolid(const Vec3d& x) {
    constexpr double h = 1e-5;
    Vec3d gradient;
    for (int axis = 0; axis < 3; ++axis)
        gradient[axis] = distanceToSolids(x + h * Vec3d::Unit(axis)) -
                         distanceToSolids(x - h * Vec3d::Unit(axis));
    return -gradient.normalized();
}

bool facesOutward(const TriangleMesh& mesh, const Vec3d& centre) {
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const auto& [a, b, c] = mesh.triangles[t];
        const Vec3d middle = (mesh.vertices[a] + mesh.vertices[b] + mesh.vertices[c]) / 3.0;
        if (mesh.normal(t).dot(middle - centre) <= 0.0)
            return false;
    }
    return true;
}

} // namespace

class TestFreeSurface : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(scene_.domain().min.isZero() && scene_.domain().max.x() == 1.0 &&
                scene_.domain().max.z() == 1.0);
        const WaterVolume water =
            WaterVolume::build(state_.fluid, kSpacing, settings_, scene_.domain());
        full_ = water.mesh();
        const SceneSolids solids(scene_);
        trimmed_ = freeSurfaceOnly(full_, FrameSolids(solids, state_), margin());
        QVERIFY(trimmed_.triangleCount() > 1000);
    }

    void noPolygonLiesAlongOrInsideASolidOrABubble() {
        // No vertex inside a solid; the edge where the mesh stops lies on one.
        double deepest = 0.0;
        std::size_t onSurface = 0;
        for (const Vec3d& v : trimmed_.vertices) {
            const double d = distanceToSolids(v);
            deepest = std::min(deepest, d);
            onSurface += std::abs(d) < 1e-3 * kSpacing ? 1 : 0;
        }
        QVERIFY(deepest > -1e-3 * kSpacing);
        QVERIFY(onSurface > 0);
        // No triangle within the margin faces the solid beside it (the water's side against a
        // wall, a body or a bubble): what is left near one runs across the way into it. (The
        // triangles along the edge, bent onto the solid, are the join.)
        const auto onSolid = [&](std::uint32_t v) {
            return std::abs(distanceToSolids(trimmed_.vertices[v])) < 1e-3 * kSpacing;
        };
        for (std::size_t t = 0; t < trimmed_.triangleCount(); ++t) {
            const auto& [a, b, c] = trimmed_.triangles[t];
            const Vec3d middle =
                (trimmed_.vertices[a] + trimmed_.vertices[b] + trimmed_.vertices[c]) / 3.0;
            if (distanceToSolids(middle) >= margin() || onSolid(a) || onSolid(b) || onSolid(c))
                continue;
            const double facing = trimmed_.normal(t).dot(intoSolid(middle));
            QVERIFY2(facing < 0.5, qPrintable(QString("a triangle at (%1, %2, %3) faces a solid")
                                                  .arg(middle.x())
                                                  .arg(middle.y())
                                                  .arg(middle.z())));
        }
        // The full mesh lies along the solids: the trimming is what leaves only the top.
        std::size_t near = 0;
        for (const Vec3d& v : full_.vertices)
            near += distanceToSolids(v) < margin() ? 1 : 0;
        QVERIFY(near > full_.vertices.size() / 2);
    }

    void theMeshMeetsTheSolidsWithNoGap() {
        // Every open edge of the free surface lies on the tank, the ball or the bubble, within
        // half a voxel: where the water mesh stops, the other surface begins, in the tank's
        // corners too.
        const double halfVoxel = 0.5 * settings_.voxelSize * kSpacing;
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
        for (const auto& [a, b, c] : trimmed_.triangles)
            for (const auto& [p, q] : {std::pair(a, b), std::pair(b, c), std::pair(c, a)})
                ++edges[{std::min(p, q), std::max(p, q)}];
        std::size_t open = 0;
        for (const auto& [edge, uses] : edges) {
            if (uses != 1)
                continue;
            ++open;
            const Vec3d middle =
                0.5 * (trimmed_.vertices[edge.first] + trimmed_.vertices[edge.second]);
            QVERIFY2(std::abs(distanceToSolids(middle)) < halfVoxel,
                     qPrintable(QString("an open edge at (%1, %2, %3), %4 m from every solid")
                                    .arg(middle.x())
                                    .arg(middle.y())
                                    .arg(middle.z())
                                    .arg(distanceToSolids(middle))));
        }
        QVERIFY(open > 100);
    }

    void theSurfaceReachesTheTankWalls() {
        // The water's sides lie in the walls' planes (the mesh spans the tank exactly), and no
        // polygon of the free surface stands off a wall facing it: the surface meets each wall
        // square on instead of rounding off short of it.
        const Aabb bounds = full_.bounds();
        for (int axis : {0, 2}) {
            QVERIFY2(std::abs(bounds.min[axis]) < 1e-6 && std::abs(bounds.max[axis] - 1.0) < 1e-6,
                     qPrintable(QString("the water spans %1 to %2 m across a 1 m tank")
                                    .arg(bounds.min[axis])
                                    .arg(bounds.max[axis])));
            const Aabb top = trimmed_.bounds();
            QVERIFY(std::abs(top.min[axis]) < 1e-6 && std::abs(top.max[axis] - 1.0) < 1e-6);
        }
        QVERIFY(std::abs(bounds.min.y()) < 1e-6);
        std::size_t alongWalls = 0;
        for (std::size_t t = 0; t < trimmed_.triangleCount(); ++t) {
            const auto& [a, b, c] = trimmed_.triangles[t];
            const Vec3d middle =
                (trimmed_.vertices[a] + trimmed_.vertices[b] + trimmed_.vertices[c]) / 3.0;
            const double toWall =
                std::min({middle.x(), 1.0 - middle.x(), middle.z(), 1.0 - middle.z()});
            if (toWall > 3.0 * kSpacing || distanceToSolids(middle) < toWall)
                continue; // not by a wall, or nearer the ball or the bubble
            ++alongWalls;
            QVERIFY2(trimmed_.normal(t).y() > 0.9,
                     qPrintable(QString("a free-surface triangle at (%1, %2, %3) faces a wall")
                                    .arg(middle.x())
                                    .arg(middle.y())
                                    .arg(middle.z())));
        }
        QVERIFY(alongWalls > 100);
    }

    void theFreeSurfaceStaysAtTheWatersHeight() {
        // Area-weighted height of what is left: the pool's top, to a tenth of a spacing.
        double area = 0.0;
        double moment = 0.0;
        for (std::size_t t = 0; t < trimmed_.triangleCount(); ++t) {
            const auto& [a, b, c] = trimmed_.triangles[t];
            const double y =
                (trimmed_.vertices[a] + trimmed_.vertices[b] + trimmed_.vertices[c]).y();
            area += trimmed_.area(t);
            moment += trimmed_.area(t) * y / 3.0;
            QVERIFY2(trimmed_.normal(t).y() > 0.0, "a free-surface triangle faces down");
        }
        const double height = moment / area;
        QVERIFY2(
            std::abs(height - kDepth) < 0.1 * kSpacing,
            qPrintable(QString("free surface at %1 m, water %2 m deep").arg(height).arg(kDepth)));
        // The whole top, wall to wall, less the discs where the bubble and the ball cut through
        // it at their equators.
        const double holes = kPi * (std::pow(kBubbleRadius, 2) + std::pow(kBallRadius, 2));
        const double expected = 1.0 - holes;
        QVERIFY2(std::abs(area / expected - 1.0) < 0.02,
                 qPrintable(QString("free surface %1 m², expected %2 m²").arg(area).arg(expected)));
    }

    void closedModeKeepsTheWholeWatertightSurface() {
        SurfaceMeshSettings closed = settings_;
        closed.mode = "closed";
        const SceneSolids solids(scene_);
        const TriangleMesh mesh =
            renderedSurface(full_, FrameSolids(solids, state_), closed, kSpacing);
        const TriangleMesh::EdgeCounts edges = mesh.countEdges();
        QCOMPARE(edges.open, std::size_t(0));
        QCOMPARE(edges.nonManifold, std::size_t(0));
        QCOMPARE(edges.misoriented, std::size_t(0));
        // Outward normals make the enclosed volume positive: the particles' own, within 3 %.
        const double water = double(state_.fluid.size()) * std::pow(kSpacing, 3);
        QVERIFY2(std::abs(mesh.signedVolume() / water - 1.0) < 0.03,
                 qPrintable(QString("encloses %1 m³ of %2").arg(mesh.signedVolume()).arg(water)));
        // The free-surface mode is the trimmed mesh.
        QCOMPARE(renderedSurface(full_, FrameSolids(solids, state_), settings_, kSpacing)
                     .triangleCount(),
                 trimmed_.triangleCount());
    }

    void aBodyIsPlacedWhereTheFrameHasIt() {
        SimulationState moved = state_;
        moved.bodies[0].position = Vec3d(0.6, 0.8, 0.4);
        moved.bodies[0].orientation = Quatd(Eigen::AngleAxisd(0.7, Vec3d::UnitZ()));
        moved.bubbles.clear();
        const SceneSolids solids(scene_);
        const FrameSolids frame(solids, moved);
        const Vec3d probe(0.6, 0.8 + kBallRadius + 0.05, 0.4);
        QVERIFY(std::abs(frame.clearance(probe) - 0.05) < 1e-12);
        // Where the bubble was, only the tank's floor is left to measure from.
        QVERIFY(std::abs(frame.clearance(kBubbleCentre) - kDepth) < 1e-12);
        const std::vector<NamedMesh> meshes = frame.meshes();
        QCOMPARE(meshes.size(), std::size_t(1));
        QCOMPARE(meshes[0].name, std::string("Ball"));
        QVERIFY(meshes[0].mesh.bounds().center().isApprox(Vec3d(0.6, 0.8, 0.4), 1e-9));
    }

    void primitiveMeshesAreClosedAndFaceOutward() {
        const TriangleMesh box = tessellateBox(Vec3d(0.2, 0.4, 0.6));
        QVERIFY(std::abs(box.signedVolume() - 0.2 * 0.4 * 0.6) < 1e-12);
        QVERIFY(facesOutward(box, Vec3d::Zero()));
        const int segments = 48;
        const TriangleMesh cylinder = tessellateCylinder(0.1, 0.5, segments);
        // A prism on the regular 48-gon inscribed in the circle.
        const double polygon = 0.5 * segments * 0.01 * std::sin(2.0 * kPi / segments);
        QVERIFY(std::abs(cylinder.signedVolume() - polygon * 0.5) < 1e-12);
        QVERIFY(facesOutward(cylinder, Vec3d::Zero()));
        const TriangleMesh sphere = tessellateSphere(0.3);
        QVERIFY(facesOutward(sphere, Vec3d::Zero()));
        const double sphereError = sphere.signedVolume() / (4.0 / 3.0 * kPi * 0.027) - 1.0;
        QVERIFY(sphereError < 0.0 && sphereError > -0.01); // 1280 triangles fall 0.86 % short
    }

private:
    double margin() const { return settings_.margin * kSpacing; }

    SurfaceMeshSettings settings_;
    Scene scene_ = poolScene();
    SimulationState state_ = poolState();
    TriangleMesh full_;
    TriangleMesh trimmed_;
};

AIRTRAP_TEST_APPLESS(TestFreeSurface)
#include "TestFreeSurface.moc"
