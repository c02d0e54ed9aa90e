// The parameter declarations: complete, taking Scene.h's defaults, addressable by dotted path and
// by the field they are bound to.
#include "scene/ParameterCodec.h"
#include "scene/SceneJson.h"
#include "scene/SceneSchema.h"
#include "support/TestMain.h"
#include "unit/SceneTestSupport.h"

#include <QtTest>
#include <regex>
#include <set>

using namespace airtrap;
using airtrap::test::contains;
using airtrap::test::errorMessage;

class TestSceneSchema : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void sectionsAreInFileOrder() {
        std::vector<std::string> keys;
        for (const SchemaSection& section : SceneSchema::sections())
            keys.push_back(section.key);
        const std::vector<std::string> expected{"",
                                                "solver",
                                                "frames",
                                                "container",
                                                "fluid_blocks",
                                                "obstacles",
                                                "emitters",
                                                "bodies",
                                                "keyframes",
                                                "bubbles",
                                                "surface_mesh",
                                                "bubble_mesh",
                                                "subgrid_bubbles"};
        QCOMPARE(keys, expected);
        QVERIFY(SceneSchema::findSection("fluid_blocks")->isArray);
        QVERIFY(!SceneSchema::findSection("solver")->isArray);
    }

    void declarationsAreComplete() {
        const std::regex snakeCase("[a-z][a-z0-9_]*");
        for (const SchemaSection& section : SceneSchema::sections()) {
            std::set<std::string> keys;
            QVERIFY(!section.label.empty() && !section.help.empty());
            for (const BoundParameter& parameter : section.parameters) {
                const ParameterDeclaration& declaration = parameter.declaration;
                const std::string path = SceneSchema::pathOf(section, 0, declaration.key);
                QVERIFY2(std::regex_match(declaration.key, snakeCase), path.c_str());
                QVERIFY2(keys.insert(declaration.key).second, path.c_str());
                QVERIFY2(!declaration.label.empty(), path.c_str());
                QVERIFY2(declaration.help.size() > 10 && declaration.help.back() == '.',
                         path.c_str());
                QVERIFY2(declaration.minimum <= declaration.maximum, path.c_str());
                const std::string problem =
                    ParameterCodec::check(declaration, declaration.defaultValue, path);
                QVERIFY2(problem.empty(), problem.c_str());
                QVERIFY2(parameter.get && parameter.set, path.c_str());
            }
        }
    }

    void aFileWithoutAKeyGetsTheStructsDefault() {
        // A file naming no parameter, one empty element in each array section: the reader fills
        // every value from the declarations, which must give what Scene.h's structs hold.
        nlohmann::json json = {{"format_version", Scene::kFormatVersion}};
        Scene expected;
        for (const SchemaSection& section : SceneSchema::sections())
            if (section.isArray) {
                json[section.key] = nlohmann::json::array({nlohmann::json::object()});
                section.resize(expected, 1);
            }
        const Scene read = sceneFromJson(json, "defaults.json");
        for (const SchemaSection& section : SceneSchema::sections())
            for (const BoundParameter& parameter : section.parameters) {
                const std::string path = SceneSchema::pathOf(section, 0, parameter.declaration.key);
                const ParameterValue value = parameter.get(read, 0);
                QVERIFY2(value == parameter.get(expected, 0),
                         (path + ": read as " + ParameterCodec::formatValue(value) +
                          ", Scene.h has " +
                          ParameterCodec::formatValue(parameter.get(expected, 0)))
                             .c_str());
            }
    }

    void keysComeFromTheDeclarations() {
        QCOMPARE(SceneSchema::keyOf(&SolverSettings::maxSpeed), std::string("solver.max_speed"));
        QCOMPARE(SceneSchema::keyOf(&SurfaceMeshSettings::voxelSize),
                 std::string("surface_mesh.voxel_size"));
        QCOMPARE(SceneSchema::keyOf(&Scene::seed), std::string("seed"));
        QCOMPARE(SceneSchema::keyOf(&FluidBlock::min, 2), std::string("fluid_blocks[2].min"));
        QCOMPARE(SceneSchema::nameOf(&InflowEmitterSettings::stopTime), std::string("stop_time"));
        // Same type, other owner: a body's position is not a keyframe's.
        QCOMPARE(SceneSchema::keyOf(&BodyKeyframe::position, 1),
                 std::string("keyframes[1].position"));
        // A field bound to no parameter is a programming error, not a silent wrong key.
        QVERIFY_THROWS_EXCEPTION(std::logic_error, SceneSchema::keyOf(&Scene::sourcePath));
    }

    void fieldsAreCheckedByTheirDeclaration() {
        Scene scene;
        QVERIFY(SceneSchema::check(scene, &SolverSettings::maxSpeed).empty());
        scene.solver.maxSpeed = -1.0;
        const std::string problem = SceneSchema::check(scene, &SolverSettings::maxSpeed);
        QVERIFY2(contains(problem, "solver.max_speed = -1 is out of range"), problem.c_str());
        scene.surfaceMesh.smoothing = 51;
        QVERIFY(contains(SceneSchema::check(scene, &SurfaceMeshSettings::smoothing),
                         "surface_mesh.smoothing = 51"));
    }

    void getAndSetReachTheField() {
        Scene scene;
        scene.fluidBlocks.resize(2);
        const ParameterPath path = SceneSchema::resolve("fluid_blocks[1].max", "test");
        path.parameter->set(scene, path.element, Vec3d(1, 2, 3));
        QCOMPARE(scene.fluidBlocks[1].max, Vec3d(1, 2, 3));
        QVERIFY(path.parameter->get(scene, 0) == ParameterValue(FluidBlock().max));

        // Spin boxes may hand a double to an integer parameter and vice versa.
        const ParameterPath endFrame = SceneSchema::resolve("frames.end_frame", "test");
        endFrame.parameter->set(scene, 0, 12.0);
        QCOMPARE(scene.frames.endFrame, 12);
        const ParameterPath fps = SceneSchema::resolve("frames.fps", "test");
        fps.parameter->set(scene, 0, 24LL);
        QCOMPARE(scene.frames.fps, 24.0);

        const std::string message = errorMessage(
            [&] { fps.parameter->set(scene, 0, std::string("fast")); }, ErrorKind::InvalidInput);
        QVERIFY2(contains(message, "fps"), message.c_str());
    }

    void resolvesDottedPaths() {
        ParameterPath path = SceneSchema::resolve("solver.particle_spacing", "test");
        QCOMPARE(path.section->key, std::string("solver"));
        QCOMPARE(path.parameter->declaration.unit, std::string("m"));
        QCOMPARE(path.text, std::string("solver.particle_spacing"));

        path = SceneSchema::resolve("obstacles[12].size", "test");
        QCOMPARE(path.element, std::size_t(12));
        QCOMPARE(path.text, std::string("obstacles[12].size"));

        path = SceneSchema::resolve("seed", "test");
        QCOMPARE(path.section->key, std::string());
        QCOMPARE(path.parameter->declaration.kind, ParameterKind::Int);

        const std::string message =
            errorMessage([] { SceneSchema::resolve("container.hedroom", "test"); });
        QVERIFY2(contains(message, "test: container.hedroom: unknown key; did you mean "
                                   "\"headroom\"? Valid keys of container: min, max, headroom"),
                 message.c_str());
    }

    void obstacleShapeIsAChoice() {
        const ParameterDeclaration& shape =
            SceneSchema::resolve("obstacles[0].shape", "test").parameter->declaration;
        QCOMPARE(shape.kind, ParameterKind::Choice);
        QCOMPARE(shape.choices, std::vector<std::string>{"box"});
    }

    void textFormsOfRanges() {
        const auto rangeOf = [](const std::string& path) {
            return ParameterCodec::rangeText(
                SceneSchema::resolve(path, "test").parameter->declaration);
        };
        QCOMPARE(rangeOf("solver.particle_spacing"), std::string("[0.001, 1]"));
        QCOMPARE(rangeOf("obstacles[0].size"), std::string("(0, 1000]"));
        QCOMPARE(rangeOf("frames.end_frame"), std::string("[2, 100000]"));
        QCOMPARE(rangeOf("name"), std::string("1 to 200 characters"));
        QCOMPARE(ParameterCodec::formatNumber(0.1), std::string("0.1"));
        QCOMPARE(ParameterCodec::formatNumber(-9.81), std::string("-9.81"));
        QCOMPARE(ParameterCodec::formatNumber(9007199254740991.0), std::string("9007199254740991"));
    }
};

AIRTRAP_TEST_APPLESS(TestSceneSchema)
#include "TestSceneSchema.moc"
