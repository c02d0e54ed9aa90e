// Cross-field validation: container corners, fluid blocks in the domain, obstacles in the
// domain, the particle cap, and overlap and block-fit warnings.
#include "sim/SceneCheck.h"
#include "support/TestMain.h"
#include "unit/SceneTestSupport.h"

#include <QtTest>

using namespace airtrap;
using airtrap::test::contains;
using airtrap::test::errorMessage;

namespace {

//! A valid scene: a 2 × 1 × 1 m tank with a water block and a box that do not touch.
Scene validScene() {
    Scene scene;
    scene.sourcePath = "tank.json";
    scene.container.max = Vec3d(2.0, 1.0, 1.0);
    FluidBlock block;
    block.max = Vec3d(0.5, 0.5, 1.0);
    scene.fluidBlocks.push_back(block);
    BoxObstacle obstacle;
    obstacle.center = Vec3d(1.5, 0.25, 0.5);
    scene.obstacles.push_back(obstacle);
    return scene;
}

std::string validationError(const Scene& scene) {
    return errorMessage([&] { validateScene(scene); });
}

} // namespace

class TestSceneValidator : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void validSceneHasNoIssues() {
        const SceneIssues issues = SceneCheck::run(validScene());
        QVERIFY(issues.ok());
        QVERIFY(issues.warnings.empty());
    }

    void containerNeedsMinBelowMax() {
        Scene scene = validScene();
        scene.container.min.z() = 1.0;
        QCOMPARE(
            validationError(scene),
            std::string("tank.json: container.min.z = 1 must be less than container.max.z = 1"));
    }

    void needsAFluidBlock() {
        Scene scene = validScene();
        scene.fluidBlocks.clear();
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "tank.json: fluid_blocks is empty"), message.c_str());
    }

    void fluidBlockMustBeInsideTheDomain() {
        Scene scene = validScene();
        scene.fluidBlocks[0].max.y() = 1.2; // above the rim, inside the 0.5 m headroom: falls in
        QVERIFY(SceneCheck::run(scene).ok());
        scene.fluidBlocks[0].max.y() = 1.6;
        std::string message = validationError(scene);
        QCOMPARE(message, std::string("tank.json: fluid_blocks[0] (\"Water\") reaches outside the "
                                      "domain (container plus headroom): max.y = 1.6 > 1.5"));
        scene = validScene();
        scene.fluidBlocks[0].min.x() = 0.6;
        message = validationError(scene);
        QVERIFY2(contains(message, "fluid_blocks[0] (\"Water\"): min.x = 0.6 must be less than "
                                   "max.x = 0.5"),
                 message.c_str());
    }

    void obstacleMustBeInsideTheDomain() {
        Scene scene = validScene();
        scene.obstacles[0].center.y() = 1.2; // reaches 1.45: inside the 0.5 m headroom
        QVERIFY(SceneCheck::run(scene).ok());
        scene.obstacles[0].center.y() = 1.4;
        const std::string message = validationError(scene);
        QCOMPARE(message, std::string("tank.json: obstacles[0] (\"Obstacle\") reaches outside the "
                                      "domain (container plus headroom): max.y = 1.65 > 1.5"));
    }

    void particleCountIsCapped() {
        Scene scene = validScene();
        scene.solver.particleSpacing = 0.001; // 0.25 m³ → 250 million particles
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "tank.json: the fluid blocks hold about 250.0 million particles "
                                   "at solver.particle_spacing = 0.001 m; the limit is 20 million. "
                                   "Use a spacing of at least 0.0023 m"),
                 message.c_str());
    }

    void particleCountAdviceStaysWithinTheDeclaredSpacings() {
        // 400 m of water on a side: 64 million particles even at the coarsest spacing, 1 m.
        Scene scene = validScene();
        scene.container.max = Vec3d(500.0, 500.0, 500.0);
        scene.fluidBlocks[0].max = Vec3d(400.0, 400.0, 400.0);
        scene.solver.particleSpacing = 1.0;
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "the limit is 20 million. Even the coarsest spacing allowed "
                                   "(1 m) gives too many: make the fluid blocks smaller."),
                 message.c_str());
    }

    void waterFasterThanMaxSpeedIsRefusedWithWcsphOnly() {
        Scene scene = validScene();
        scene.solver.maxSpeed = 2.0;
        scene.fluidBlocks[0].initialVelocity = Vec3d(0.0, -3.0, 4.0);
        const std::string message = validationError(scene);
        QVERIFY2(contains(message,
                          "fluid_blocks[0] (\"Water\").initial_velocity's speed is 5 m/s, "
                          "above solver.max_speed = 2 m/s, the basis of the speed of sound "
                          "(WCSPH): raise solver.max_speed to at least 5"),
                 message.c_str());
        scene.solver.method = "dfsph";
        QVERIFY(SceneCheck::run(scene).ok());
    }

    void overlapsAreWarnings() {
        Scene scene = validScene();
        scene.obstacles[0].center.x() = 0.5;
        FluidBlock second;
        second.name = "Second";
        second.min = Vec3d(0.4, 0.0, 0.0);
        second.max = Vec3d(0.8, 0.4, 0.6);
        scene.fluidBlocks.push_back(second);
        const std::vector<std::string> warnings = validateScene(scene);
        QCOMPARE(warnings.size(), std::size_t(3));
        QVERIFY2(contains(warnings[0], "fluid_blocks[0] (\"Water\") overlaps fluid_blocks[1] "
                                       "(\"Second\")"),
                 warnings[0].c_str());
        QVERIFY2(contains(warnings[1], "fluid_blocks[0] (\"Water\") overlaps obstacles[0]"),
                 warnings[1].c_str());
        QVERIFY2(contains(warnings[2], "fluid_blocks[1] (\"Second\") overlaps obstacles[0]"),
                 warnings[2].c_str());
    }

    void manyOverlapsAreCountedNotListed() {
        // 100 blocks stacked on the same box: 4 950 overlapping pairs.
        Scene scene = validScene();
        scene.obstacles.clear();
        scene.solver.particleSpacing = 0.05;
        for (int k = 1; k < 100; ++k)
            scene.fluidBlocks.push_back(scene.fluidBlocks[0]);
        const std::vector<std::string> warnings = validateScene(scene);
        QCOMPARE(warnings.size(), std::size_t(11));
        QVERIFY2(contains(warnings.back(),
                          "and 4940 more overlapping pairs of fluid blocks and obstacles"),
                 warnings.back().c_str());
    }

    void saysHowDeepABlockIsFilledWhenNotWholeSpacings() {
        Scene scene = validScene();
        scene.solver.particleSpacing = 0.02;
        scene.fluidBlocks[0].max.y() = 0.55; // 27.5 spacings: filled 28 layers deep
        const std::vector<std::string> warnings = validateScene(scene);
        QCOMPARE(warnings.size(), std::size_t(1));
        QVERIFY2(contains(warnings[0],
                          "tank.json: fluid_blocks[0] (\"Water\") is 0.55 m along y, not a whole "
                          "number of solver.particle_spacing = 0.02 m: it is filled with 28 "
                          "layers, 0.56 m of water (max.y = 0.56 would draw exactly that)"),
                 warnings[0].c_str());
    }

    //! Rounded to the nearest, the lattice would reach past the tank's wall and squeeze its
    //! last layer into the wall's boundary particles.
    void aBlockIsNeverFilledPastTheContainer() {
        Scene scene = validScene();
        scene.solver.particleSpacing = 0.0115; // the block's 1 m along z: 86.96 spacings
        scene.fluidBlocks[0].max = Vec3d(0.506, 0.506, 1.0); // 44 whole spacings along x, y
        const std::vector<std::string> warnings = validateScene(scene);
        QCOMPARE(warnings.size(), std::size_t(1));
        QVERIFY2(contains(warnings[0],
                          "is 1 m along z, not a whole number of solver.particle_spacing = 0.0115 "
                          "m: it is filled with 86 layers, 0.989 m of water, as many as fit inside "
                          "the container (max.z = 0.989 would draw exactly that)"),
                 warnings[0].c_str());
        QCOMPARE(scene.fluidBlocks[0].layers(2, 0.0115, scene.domain().max.z()), 86);
    }

    void touchingBoxesDoNotOverlap() {
        Scene scene = validScene();
        scene.obstacles[0].center = Vec3d(0.6, 0.25, 0.5); // x from 0.5: touches the block
        QVERIFY(validateScene(scene).empty());
    }

    void fieldRangesAreCheckedToo() {
        Scene scene = validScene();
        scene.solver.cflFactor = 2.0;
        scene.sourcePath.clear();
        QCOMPARE(validationError(scene),
                 std::string("scene: solver.cfl_factor = 2 is out of range; expected a number in "
                             "[0.05, 0.6]"));
    }

    void pressureSolverSettingsAreChecked() {
        Scene scene = validScene();
        scene.solver.method = "pcisph";
        scene.sourcePath.clear();
        const std::string unknown = validationError(scene);
        QVERIFY2(contains(unknown, "solver.method") && contains(unknown, "\"dfsph\""),
                 unknown.c_str());
        scene.solver.method = "dfsph";
        scene.solver.minIterations = 5;
        scene.solver.maxIterations = 3;
        QCOMPARE(validationError(scene), std::string("scene: solver.min_iterations = 5 exceeds "
                                                     "solver.max_iterations = 3"));
        scene.solver.maxIterations = 100;
        scene.solver.minTimeStep = 0.01;
        scene.solver.maxTimeStep = 0.005;
        QCOMPARE(validationError(scene), std::string("scene: solver.min_time_step = 0.01 s exceeds "
                                                     "solver.max_time_step = 0.005 s"));
    }

    void bubbleRestitutionsAreOrdered() {
        Scene scene = validScene();
        scene.bubbles.approachRestitution = -0.1;
        scene.bubbles.overlapRestitution = -0.5;
        QCOMPARE(validationError(scene),
                 std::string("tank.json: bubbles.approach_restitution = -0.1 exceeds "
                             "bubbles.overlap_restitution = -0.5; approaching bubbles take at most "
                             "the overlapping ones' restitution (ε₁ ≤ ε₂ ≤ 0)"));
        scene.bubbles.approachRestitution = -1.0;
        scene.bubbles.overlapRestitution = -1.0;
        QVERIFY(validateScene(scene).empty());
    }

    void bubbleRiseCapWithinMaxSpeed() {
        Scene scene = validScene();
        scene.bubbles.enabled = true;
        scene.solver.maxSpeed = 2.0;
        scene.bubbles.maxRiseSpeed = 3.0;
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "bubbles.max_rise_speed = 3 m/s exceeds solver.max_speed = "
                                   "2 m/s"),
                 message.c_str());
    }

    void surfaceParticlesSpanOneAndAHalfVoxels() {
        Scene scene = validScene();
        scene.surfaceMesh.voxelSize = 1.0;
        scene.surfaceMesh.particleRadius = 1.2;
        QCOMPARE(validationError(scene),
                 std::string("tank.json: surface_mesh.particle_radius = 1.2 is less than 1.5 × "
                             "surface_mesh.voxel_size = 1.5; particles narrower than 1.5 voxels "
                             "would leave holes in the water mesh"));
        scene.surfaceMesh.particleRadius = 1.5;
        QVERIFY(validateScene(scene).empty());
    }
};

AIRTRAP_TEST_APPLESS(TestSceneValidator)
#include "TestSceneValidator.moc"
