// Scene files: the samples, round trips, and the messages for every kind of bad input (each must
// name the file, the JSON path, the value and the allowed range).
#include "scene/SceneJson.h"
#include "sim/SceneCheck.h"
#include "support/TestMain.h"
#include "unit/SceneTestSupport.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <sstream>

using namespace airtrap;
using airtrap::test::contains;
using airtrap::test::errorMessage;

namespace {

const std::string kSamples = std::string(AIRTRAP_SOURCE_DIR) + "/samples/";

//! A valid scene as JSON, to be broken one key at a time.
nlohmann::json validJson() {
    Scene scene;
    scene.fluidBlocks.resize(2);
    scene.obstacles.resize(1);
    return sceneToJson(scene);
}

std::string readError(const nlohmann::json& json) {
    return errorMessage([&] { sceneFromJson(json, "scene.json"); });
}

} // namespace

class TestSceneJson : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void samplesLoadAndValidate_data() {
        QTest::addColumn<QString>("file");
        QTest::newRow("dam_break") << "dam_break.json";
        QTest::newRow("hydrostatic") << "hydrostatic.json";
        QTest::newRow("pouring") << "pouring.json";
        QTest::newRow("bubble_column") << "bubble_column.json";
        // Bodies placed in the water on purpose: notes, no warnings.
        QTest::newRow("buoyancy") << "buoyancy.json";
        QTest::newRow("diving_bunny") << "diving_bunny.json";
    }

    void samplesLoadAndValidate() {
        QFETCH(QString, file);
        const std::string path = kSamples + file.toStdString();
        const Scene scene = readSceneFile(path);
        QCOMPARE(scene.sourcePath, path);
        QVERIFY(!scene.fluidBlocks.empty());
        const std::vector<std::string> warnings = validateScene(scene);
        QVERIFY2(warnings.empty(), warnings.empty() ? "" : warnings.front().c_str());
        // The samples were written by writeSceneFile, so they are in canonical form.
        QCOMPARE(test::readText(path), sceneToText(scene));
    }

    void damBreakMatchesTheSetup() {
        const Scene scene = readSceneFile(kSamples + "dam_break.json");
        QCOMPARE(scene.solver.particleSpacing, 0.02);
        QCOMPARE(scene.solver.maxSpeed, 6.0);
        QVERIFY(scene.container.max.isApprox(Vec3d(2.5, 2.0, 0.4))); // tall: the run-up stays in
        QVERIFY(scene.fluidBlocks.at(0).max.isApprox(Vec3d(0.5, 1.0, 0.4)));
        QCOMPARE(scene.frames.endFrame, 60);
    }

    void defaultSceneRoundTrips() {
        const Scene original;
        const Scene copy = sceneFromJson(sceneToJson(original), "round trip");
        QCOMPARE(sceneToJson(copy), sceneToJson(original));
        QCOMPARE(sceneToText(copy), sceneToText(original));
        QCOMPARE(copy.name, original.name);
        QCOMPARE(copy.solver.gravity, original.solver.gravity);
        QCOMPARE(copy.frames.endFrame, original.frames.endFrame);
    }

    void sceneWithArraysRoundTrips() {
        Scene original;
        original.fluidBlocks.resize(2);
        original.fluidBlocks[1].initialVelocity = Vec3d(0.1, -0.25, 1.0 / 3.0);
        original.obstacles.resize(1);
        original.seed = 9007199254740991ULL;
        const Scene copy = sceneFromText(sceneToText(original), "round trip");
        QCOMPARE(sceneToJson(copy), sceneToJson(original));
        QCOMPARE(copy.fluidBlocks[1].initialVelocity, original.fluidBlocks[1].initialVelocity);
        QCOMPARE(copy.seed, original.seed);
    }

    void missingKeysTakeDefaults() {
        const Scene scene = sceneFromJson({{"format_version", 1}}, "minimal.json");
        QCOMPARE(sceneToJson(scene), sceneToJson(Scene()));
        const Scene partial =
            sceneFromJson({{"format_version", 1}, {"fluid_blocks", {{{"name", "A"}}}}}, "x.json");
        QCOMPARE(partial.fluidBlocks.at(0).max, FluidBlock().max);
    }

    void malformedJsonNamesFileAndLine() {
        QTemporaryDir folder;
        const std::string path = test::writeFile(
            folder, "broken.json",
            "{\n    \"format_version\": 1,\n    \"name\": \"x\"\n    \"seed\": 2\n}\n");
        const std::string message = errorMessage([&] { readSceneFile(path); });
        QVERIFY2(contains(message, path + ": malformed JSON at line 4, column"), message.c_str());
    }

    void aNumberBeyondADoubleNamesFileAndLine() {
        QTemporaryDir folder;
        const std::string path = test::writeFile(
            folder, "huge.json",
            "{\n    \"format_version\": 1,\n    \"solver\": {\"max_speed\": 1e999}\n}\n");
        const std::string message = errorMessage([&] { readSceneFile(path); });
        QVERIFY2(contains(message, path + ": malformed JSON at line 3, column 29: the number 1e999 "
                                          "is too large for a double"),
                 message.c_str());
    }

    void aKeyTwiceInOneObjectIsRefusedNamingBothPlaces() {
        QTemporaryDir folder;
        const std::string path =
            test::writeFile(folder, "twice.json",
                            "{\n    \"format_version\": 1,\n"
                            "    \"solver\": {\"max_speed\": 4,\n"
                            "               \"max_speed\": 6},\n"
                            "    \"name\": \"\\\"max_speed\\\": no key\"\n}\n");
        const std::string message = errorMessage([&] { readSceneFile(path); });
        QVERIFY2(contains(message, path + ": key \"max_speed\" appears twice in the same object, "
                                          "at line 3, column 16 and line 4, column 16"),
                 message.c_str());
        // The same key in two objects is no duplicate.
        const Scene scene = sceneFromText(
            R"({"format_version": 1, "name": "a", "fluid_blocks": [{"name": "b"}, {"name": "c"}]})",
            "ok.json");
        QCOMPARE(scene.fluidBlocks.at(1).name, std::string("c"));
    }

    void unknownKeyNamesPathAndSuggests() {
        nlohmann::json json = validJson();
        json["solver"]["particle_spacng"] = 0.02;
        std::string message = readError(json);
        QVERIFY2(contains(message, "scene.json: solver.particle_spacng: unknown key; did you mean "
                                   "\"particle_spacing\"?"),
                 message.c_str());
        QVERIFY2(
            contains(message, "Valid keys of solver: method, particle_spacing, support_factor"),
            message.c_str());

        json = validJson();
        json["solvr"] = nlohmann::json::object();
        message = readError(json);
        QVERIFY2(contains(message, "scene.json: solvr: unknown key; did you mean \"solver\"?"),
                 message.c_str());

        json = validJson();
        json["fluid_blocks"][1]["colour"] = "blue";
        message = readError(json);
        QVERIFY2(contains(message, "scene.json: fluid_blocks[1].colour: unknown key; valid keys "
                                   "of fluid_blocks: name, min, max, initial_velocity"),
                 message.c_str());
    }

    void outOfRangeNamesPathValueAndRange() {
        nlohmann::json json = validJson();
        json["solver"]["particle_spacing"] = -0.01;
        std::string message = readError(json);
        QCOMPARE(message,
                 std::string("scene.json: solver.particle_spacing = -0.01 is out of range; "
                             "expected a number in [0.001, 1] m"));

        json = validJson();
        json["frames"]["end_frame"] = 1;
        message = readError(json);
        QCOMPARE(message, std::string("scene.json: frames.end_frame = 1 is out of range; expected "
                                      "an integer in [2, 100000]"));

        json = validJson();
        json["obstacles"][0]["size"] = {0.2, 0.0, 0.2};
        message = readError(json);
        QCOMPARE(message,
                 std::string("scene.json: obstacles[0].size = [0.2, 0, 0.2] is out of "
                             "range; expected an array of 3 numbers, each in (0, 1000] m"));
    }

    void wrongTypeNamesPathValueAndRange() {
        nlohmann::json json = validJson();
        json["fluid_blocks"][1]["min"] = "abc";
        std::string message = readError(json);
        QCOMPARE(message, std::string("scene.json: fluid_blocks[1].min: expected an array of 3 "
                                      "numbers, each in [-1000, 1000] m, got \"abc\""));

        json = validJson();
        json["frames"]["end_frame"] = 2.5;
        message = readError(json);
        QVERIFY2(contains(message, "frames.end_frame: expected an integer in [2, 100000], got 2.5"),
                 message.c_str());

        json = validJson();
        json["solver"] = 3;
        message = readError(json);
        QVERIFY2(contains(message, "scene.json: solver: expected an object, got 3"),
                 message.c_str());

        json = validJson();
        json["obstacles"] = {{"name", "x"}};
        message = readError(json);
        QVERIFY2(contains(message, "obstacles: expected an array of objects"), message.c_str());
    }

    void wholeNumberFloatIsAnInteger() {
        nlohmann::json json = validJson();
        json["frames"]["end_frame"] = 90.0;
        QCOMPARE(sceneFromJson(json, "x").frames.endFrame, 90);
    }

    void badChoiceListsTheChoices() {
        nlohmann::json json = validJson();
        json["obstacles"][0]["shape"] = "sphere";
        const std::string message = readError(json);
        QCOMPARE(message, std::string("scene.json: obstacles[0].shape = \"sphere\" is not one of "
                                      "the choices; expected one of \"box\""));
    }

    void everyErrorIsReported() {
        nlohmann::json json = validJson();
        json["solver"]["cfl_factor"] = 5;
        json["container"]["headroom"] = "high";
        json["seed"] = -1;
        const std::string message = readError(json);
        QCOMPARE(std::count(message.begin(), message.end(), '\n'), 2L);
        QVERIFY2(contains(message, "scene.json: seed = -1 is out of range"), message.c_str());
        QVERIFY2(contains(message, "scene.json: solver.cfl_factor = 5 is out of range; expected a "
                                   "number in [0.05, 0.6]"),
                 message.c_str());
        QVERIFY2(contains(message, "scene.json: container.headroom: expected a number in [0, 100] "
                                   "m, got \"high\""),
                 message.c_str());
    }

    void formatVersionIsChecked() {
        nlohmann::json json = validJson();
        json.erase("format_version");
        std::string message = readError(json);
        QVERIFY2(contains(message, "scene.json: format_version is missing"), message.c_str());

        json["format_version"] = 2;
        message = readError(json);
        QVERIFY2(contains(message, "scene.json: written by a newer Airtrap (format_version 2)"),
                 message.c_str());

        json["format_version"] = 0;
        message = readError(json);
        QVERIFY2(contains(message, "format_version = 0 is out of range; expected an integer in "
                                   "[1, 1]"),
                 message.c_str());

        json["format_version"] = "1";
        message = readError(json);
        QVERIFY2(contains(message, "format_version: expected an integer"), message.c_str());
    }

    void topLevelMustBeAnObject() {
        const std::string message = readError(nlohmann::json::array({1, 2}));
        QVERIFY2(contains(message, "scene.json: expected a JSON object at the top level"),
                 message.c_str());
    }

    void unreadableFileIsAnIoError() {
        const std::string path = "/nonexistent/scene.json";
        const std::string message = errorMessage([&] { readSceneFile(path); }, ErrorKind::Io);
        QVERIFY2(contains(message, path), message.c_str());
    }

    void writeIsAtomicAndReadsBack() {
        QTemporaryDir folder;
        const std::string path = folder.path().toStdString() + "/scene.json";
        Scene scene;
        scene.fluidBlocks.resize(1);
        writeSceneFile(scene, path);
        scene.name = "Second";
        writeSceneFile(scene, path);
        QCOMPARE(readSceneFile(path).name, std::string("Second"));
        QCOMPARE(QDir(folder.path()).entryList(QDir::Files), QStringList{"scene.json"});

        const std::string badPath = folder.path().toStdString() + "/missing/scene.json";
        const std::string message =
            errorMessage([&] { writeSceneFile(scene, badPath); }, ErrorKind::Io);
        QVERIFY2(contains(message, badPath), message.c_str());
    }

    void parameterHashIsStableAndSensitive() {
        Scene scene = readSceneFile(kSamples + "dam_break.json");
        const std::string hash = parameterHash(scene);
        QCOMPARE(hash.size(), std::size_t(16));
        QVERIFY(hash.find_first_not_of("0123456789abcdef") == std::string::npos);
        QCOMPARE(parameterHash(sceneFromText(sceneToText(scene), "copy")), hash);

        Scene renamed = scene;
        renamed.name = "Another name";
        renamed.sourcePath = "elsewhere.json";
        QCOMPARE(parameterHash(renamed), hash);

        Scene extended = scene; // baking further continues the same cache
        extended.frames.endFrame += 30;
        QCOMPARE(parameterHash(extended), hash);

        Scene changed = scene;
        changed.frames.fps = 24.0;
        QVERIFY(parameterHash(changed) != hash);
        changed = scene;
        changed.solver.particleSpacing = 0.021;
        QVERIFY(parameterHash(changed) != hash);
        changed = scene;
        changed.fluidBlocks[0].max.y() += 1e-9;
        QVERIFY(parameterHash(changed) != hash);
    }

    void renderSettingsDoNotChangeTheBakesHash() {
        Scene scene = Scene();
        const std::string hash = parameterHash(scene);
        scene.surfaceMesh.smoothing = 9;
        scene.bubbleMesh.magnitude = 0.2;
        scene.subgridBubbles.maxSize *= 2.0;
        QCOMPARE(parameterHash(scene), hash);
        scene.solver.viscosityAlpha = 0.2;
        QVERIFY(parameterHash(scene) != hash);
    }
};

AIRTRAP_TEST_APPLESS(TestSceneJson)
#include "TestSceneJson.moc"
