// Scene checks for rigid bodies (docs/SCENE_FORMAT.md "Validation"): what cannot be baked is
// refused with the JSON path, the value and what was expected; bodies overlapping the water, an
// obstacle or each other at t = 0 are warned about before a bake.
#include "sim/SceneCheck.h"
#include "support/TestMain.h"
#include "unit/MeshTestSupport.h"
#include "unit/SceneTestSupport.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace airtrap;
using airtrap::test::contains;
using airtrap::test::errorMessage;

namespace {

//! A 1 m tank, a pool 0.3 m deep on its left half, one dynamic box in the air on the right.
Scene sceneWithABox() {
    Scene scene;
    scene.sourcePath = "tank.json";
    scene.solver.particleSpacing = 0.05;
    FluidBlock pool;
    pool.name = "Pool";
    pool.max = Vec3d(0.5, 0.3, 1.0);
    scene.fluidBlocks.push_back(pool);
    RigidBodySettings box;
    box.name = "Crate";
    box.size = Vec3d(0.2, 0.2, 0.2);
    box.position = Vec3d(0.75, 0.6, 0.5);
    scene.bodies.push_back(box);
    return scene;
}

std::string validationError(const Scene& scene) {
    return errorMessage([&] { validateScene(scene); });
}

} // namespace

class TestBodyValidation : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void aBodyClearOfEverythingIsFine() {
        const SceneIssues issues = SceneCheck::run(sceneWithABox());
        QVERIFY(issues.ok());
        QVERIFY(issues.warnings.empty());
    }

    void missingMeshNamesTheFile() {
        Scene scene = sceneWithABox();
        scene.bodies[0].shape = "mesh";
        scene.bodies[0].mesh = "meshes/nowhere.obj";
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "bodies[0] (\"Crate\").mesh") &&
                     contains(message, "meshes/nowhere.obj"),
                 message.c_str());
    }

    void openMeshIsRefusedWithTheReason() {
        QTemporaryDir folder;
        const std::string path = airtrap::test::writeFile(
            folder, "sheet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
        Scene scene = sceneWithABox();
        scene.sourcePath = folder.path().toStdString() + "/scene.json";
        scene.bodies[0].shape = "mesh";
        scene.bodies[0].mesh = "sheet.obj";
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, path) && contains(message, "not closed"), message.c_str());
    }

    void aMeshScaledBeyondTheDomainIsRefusedBeforeItIsSampled() {
        // 10 km across at a 5 cm spacing: sampled, its distance field alone would need
        // terabytes. Refused from the mesh's bounds, at once.
        QTemporaryDir folder;
        airtrap::test::writeObj(folder.filePath("cube.obj"), airtrap::test::cube(10.0));
        Scene scene = sceneWithABox();
        scene.sourcePath = folder.path().toStdString() + "/scene.json";
        scene.bodies[0].shape = "mesh";
        scene.bodies[0].mesh = "cube.obj";
        scene.bodies[0].meshScale = 1000.0;
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "bodies[0] (\"Crate\").mesh_scale: the mesh scaled by 1000 is "
                                   "17320.51 m across, larger than the domain"),
                 message.c_str());
    }

    void emptyMeshPathIsRefused() {
        Scene scene = sceneWithABox();
        scene.bodies[0].shape = "mesh";
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "bodies[0] (\"Crate\").mesh is empty"), message.c_str());
    }

    void bodiesSmallerThanASpacingAreRefused() {
        Scene scene = sceneWithABox();
        scene.bodies[0].shape = "sphere";
        scene.bodies[0].radius = 0.02;
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "bodies[0] (\"Crate\").radius = 0.02 m is less than "
                                   "solver.particle_spacing = 0.05 m"),
                 message.c_str());
    }

    void namesMustDiffer() {
        Scene scene = sceneWithABox();
        scene.bodies.push_back(scene.bodies[0]);
        scene.bodies[1].position.x() = 0.3;
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "bodies[1] (\"Crate\") has the name of bodies[0]"),
                 message.c_str());
    }

    void keyframesNeedAKinematicBody() {
        Scene scene = sceneWithABox();
        scene.keyframes = {{"Lid", 0.0, Vec3d(0.75, 0.6, 0.5), Vec3d::Zero()},
                           {"Crate", 0.5, Vec3d(0.75, 0.6, 0.5), Vec3d::Zero()}};
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "keyframes[0].body = \"Lid\" names no body"), message.c_str());
        QVERIFY2(contains(message, "keyframes[1].body = \"Crate\" is dynamic; keyframes move "
                                   "kinematic bodies only"),
                 message.c_str());
    }

    void keyframeTimesMustDiffer() {
        Scene scene = sceneWithABox();
        scene.bodies[0].motion = "kinematic";
        scene.keyframes = {{"Crate", 0.5, Vec3d(0.75, 0.6, 0.5), Vec3d::Zero()},
                           {"Crate", 0.5, Vec3d(0.7, 0.6, 0.5), Vec3d::Zero()}};
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "keyframes[1].time = 0.5 s repeats keyframes[0]"),
                 message.c_str());
    }

    void bodyOutsideTheDomainIsRefused() {
        Scene scene = sceneWithABox();
        scene.bodies[0].position.x() = 0.95;
        const std::string message = validationError(scene);
        QVERIFY2(contains(message, "bodies[0] (\"Crate\") reaches outside the domain") &&
                     contains(message, "along x"),
                 message.c_str());
    }

    void overlapsAtTheStartAreWarnings() {
        Scene scene = sceneWithABox();
        scene.bodies[0].position = Vec3d(0.25, 0.25, 0.5); // half in the pool
        RigidBodySettings ball;
        ball.name = "Ball";
        ball.shape = "sphere";
        ball.radius = 0.1;
        ball.position = Vec3d(0.25, 0.4, 0.5); // sunk 5 cm into the crate's top
        scene.bodies.push_back(ball);
        BoxObstacle pillar;
        pillar.center = Vec3d(0.25, 0.55, 0.5);
        pillar.size = Vec3d(0.1, 0.2, 0.1); // 5 cm into the ball
        scene.obstacles.push_back(pillar);
        std::vector<std::string> notes;
        const std::vector<std::string> warnings = validateScene(scene, &notes);
        std::string all;
        for (const std::string& warning : warnings)
            all += warning + "\n";
        // A body in the water is placed there on purpose (a floating crate): a note only.
        QCOMPARE(notes.size(), std::size_t(1));
        QVERIFY2(contains(notes[0], "bodies[0] (\"Crate\") starts in fluid_blocks[0] (\"Pool\"); "
                                    "the body displaces it"),
                 notes[0].c_str());
        QVERIFY2(!contains(all, "fluid_blocks"), all.c_str());
        QVERIFY2(contains(all, "bodies[1] (\"Ball\") overlaps obstacles[0]"), all.c_str());
        QVERIFY2(contains(all, "bodies[1] (\"Ball\") overlaps bodies[0] (\"Crate\")"), all.c_str());
        QVERIFY2(!contains(all, "overlaps the container"), all.c_str());
    }

    void aSphereBesideTheBlocksCornerDoesNotTouchIt() {
        Scene scene = sceneWithABox();
        scene.bodies[0].shape = "sphere";
        scene.bodies[0].radius = 0.1;
        // Its bounding box overlaps the pool's top corner edge; the sphere itself stays clear.
        scene.bodies[0].position = Vec3d(0.58, 0.38, 0.5); // 11 cm from the edge
        std::vector<std::string> notes;
        QVERIFY(validateScene(scene, &notes).empty());
        QVERIFY(notes.empty());
        scene.bodies[0].position = Vec3d(0.52, 0.32, 0.5); // now it dips into the water
        QVERIFY(validateScene(scene, &notes).empty());
        QCOMPARE(notes.size(), std::size_t(1));
    }

    void restingOnTheFloorIsNotAnOverlap() {
        Scene scene = sceneWithABox();
        scene.bodies[0].position.y() = 0.1; // bottom face on the floor
        QVERIFY(validateScene(scene).empty());
    }
};

AIRTRAP_TEST_APPLESS(TestBodyValidation)
#include "TestBodyValidation.moc"
