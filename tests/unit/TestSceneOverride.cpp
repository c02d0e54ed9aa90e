// `--set path=value`: every kind of value, array elements, and the messages for bad assignments.
#include "scene/SceneOverride.h"
#include "support/TestMain.h"
#include "unit/SceneTestSupport.h"

#include <QtTest>

using namespace airtrap;
using airtrap::test::contains;
using airtrap::test::errorMessage;

namespace {

Scene sceneWithBlocks() {
    Scene scene;
    scene.fluidBlocks.resize(2);
    scene.obstacles.resize(1);
    return scene;
}

std::string overrideError(const std::string& assignment) {
    Scene scene = sceneWithBlocks();
    return errorMessage([&] { applySceneOverride(scene, assignment); });
}

} // namespace

class TestSceneOverride : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void setsReal() {
        Scene scene = sceneWithBlocks();
        applySceneOverride(scene, "solver.particle_spacing=0.01");
        QCOMPARE(scene.solver.particleSpacing, 0.01);
        applySceneOverride(scene, " frames.fps = 24 ");
        QCOMPARE(scene.frames.fps, 24.0);
    }

    void setsInt() {
        Scene scene = sceneWithBlocks();
        applySceneOverride(scene, "frames.end_frame=10");
        QCOMPARE(scene.frames.endFrame, 10);
        applySceneOverride(scene, "seed=42");
        QCOMPARE(scene.seed, std::uint64_t(42));
    }

    void setsVectorWithOrWithoutBrackets() {
        Scene scene = sceneWithBlocks();
        applySceneOverride(scene, "fluid_blocks[0].max=[1,2,0.5]");
        QCOMPARE(scene.fluidBlocks[0].max, Vec3d(1, 2, 0.5));
        applySceneOverride(scene, "solver.gravity=0, -3.7, 0");
        QCOMPARE(scene.solver.gravity, Vec3d(0, -3.7, 0));
    }

    void setsStringBareOrQuoted() {
        Scene scene = sceneWithBlocks();
        applySceneOverride(scene, "name=foo");
        QCOMPARE(scene.name, std::string("foo"));
        applySceneOverride(scene, "name=\"Dam break, fine\"");
        QCOMPARE(scene.name, std::string("Dam break, fine"));
        applySceneOverride(scene, "name=123");
        QCOMPARE(scene.name, std::string("123"));
    }

    void setsArrayElement() {
        Scene scene = sceneWithBlocks();
        applySceneOverride(scene, "fluid_blocks[1].name=Second");
        applySceneOverride(scene, "obstacles[0].center=0.2,0.1,0.3");
        applySceneOverride(scene, "obstacles[0].shape=box");
        QCOMPARE(scene.fluidBlocks[1].name, std::string("Second"));
        QCOMPARE(scene.fluidBlocks[0].name, std::string("Water"));
        QCOMPARE(scene.obstacles[0].center, Vec3d(0.2, 0.1, 0.3));
    }

    void outOfRangeNamesSetPathValueAndRange() {
        QCOMPARE(overrideError("solver.particle_spacing=-0.01"),
                 std::string("--set: solver.particle_spacing = -0.01 is out of range; expected a "
                             "number in [0.001, 1] m"));
        QCOMPARE(overrideError("frames.end_frame=abc"),
                 std::string("--set: frames.end_frame: expected an integer in [2, 100000], got "
                             "\"abc\""));
        QCOMPARE(overrideError("obstacles[0].shape=sphere"),
                 std::string("--set: obstacles[0].shape = \"sphere\" is not one of the choices; "
                             "expected one of \"box\""));
        const std::string message = overrideError("fluid_blocks[0].min=1,2");
        QVERIFY2(contains(message, "expected an array of 3 numbers"), message.c_str());
    }

    void unknownKeyListsTheSectionsKeys() {
        std::string message = overrideError("solver.particle_spacng=0.02");
        QVERIFY2(contains(message,
                          "--set: solver.particle_spacng: unknown key; did you mean "
                          "\"particle_spacing\"? Valid keys of solver: method, particle_spacing, "
                          "support_factor, rest_density"),
                 message.c_str());
        message = overrideError("solvr.fps=3");
        QVERIFY2(contains(message, "--set: solvr: unknown key; did you mean \"solver\"? Valid "
                                   "keys: name, seed, solver.<key>, frames.<key>"),
                 message.c_str());
        message = overrideError("fluid_blocks.max=1,2,3");
        QVERIFY2(contains(message, "fluid_blocks is a list; address one element, e.g. "
                                   "fluid_blocks[0].max"),
                 message.c_str());
        message = overrideError("solver=1");
        QVERIFY2(contains(message, "solver is a section"), message.c_str());
        message = overrideError("fluid_blocks[x].max=1,2,3");
        QVERIFY2(contains(message, "malformed path"), message.c_str());
    }

    void missingElementIsAnError() {
        const std::string message = overrideError("fluid_blocks[2].name=x");
        QCOMPARE(message, std::string("--set: fluid_blocks[2] does not exist; fluid_blocks has 2 "
                                      "elements"));
    }

    void missingEqualsIsAnError() {
        const std::string message = overrideError("frames.end_frame");
        QVERIFY2(contains(message, "--set: expected key=value"), message.c_str());
    }

    void failedOverridesLeaveTheSceneUnchanged() {
        Scene scene = sceneWithBlocks();
        const std::string message = errorMessage([&] {
            applySceneOverrides(scene, {"frames.end_frame=10", "frames.fps=0", "seed=-2"});
        });
        QCOMPARE(scene.frames.endFrame, Scene().frames.endFrame);
        QVERIFY2(contains(message, "frames.fps = 0 is out of range"), message.c_str());
        QVERIFY2(contains(message, "\n--set: seed = -2 is out of range"), message.c_str());

        applySceneOverrides(scene, {"frames.end_frame=10", "frames.fps=25"});
        QCOMPARE(scene.frames.endFrame, 10);
        QCOMPARE(scene.frames.fps, 25.0);
    }
};

AIRTRAP_TEST_APPLESS(TestSceneOverride)
#include "TestSceneOverride.moc"
