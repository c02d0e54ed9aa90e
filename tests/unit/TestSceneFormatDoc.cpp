// docs/SCENE_FORMAT.md must be exactly what sceneFormatMarkdown() generates from the declarations.
#include "scene/SceneFormatDoc.h"
#include "scene/SceneJson.h"
#include "scene/SceneSchema.h"
#include "sim/SceneCheck.h"
#include "support/TestMain.h"
#include "unit/SceneTestSupport.h"

#include <QtTest>
#include <fstream>
#include <sstream>

using namespace airtrap;

namespace {

const std::string kDocument = std::string(AIRTRAP_SOURCE_DIR) + "/docs/SCENE_FORMAT.md";
const std::string kGenerated = std::string(AIRTRAP_BINARY_DIR) + "/tests/SCENE_FORMAT.md";

//! "line N: expected … / found …" for the first line where the texts differ.
std::string firstDifference(const std::string& expected, const std::string& actual) {
    std::istringstream a(expected);
    std::istringstream b(actual);
    std::string lineA;
    std::string lineB;
    for (int line = 1;; ++line) {
        const bool moreA = static_cast<bool>(std::getline(a, lineA));
        const bool moreB = static_cast<bool>(std::getline(b, lineB));
        if (!moreA && !moreB)
            return "texts differ only in line endings";
        if (lineA != lineB || moreA != moreB)
            return "line " + std::to_string(line) + ": generated \"" + lineA + "\", committed \"" +
                   lineB + "\"";
    }
}

} // namespace

class TestSceneFormatDoc : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void documentIsUpToDate() {
        const std::string generated = sceneFormatMarkdown();
        std::ofstream(kGenerated, std::ios::binary) << generated;
        const std::string committed = test::readText(kDocument);
        if (committed == generated)
            return;
        const std::string message = "docs/SCENE_FORMAT.md is out of date (" +
                                    firstDifference(generated, committed) +
                                    "). Regenerate it with: cp " + kGenerated + " " + kDocument;
        QFAIL(message.c_str());
    }

    void everyKeyIsDocumented() {
        const std::string document = sceneFormatMarkdown();
        for (const SchemaSection& section : SceneSchema::sections()) {
            if (!section.key.empty())
                QVERIFY2(test::contains(document, "## `" + section.key + "`"), section.key.c_str());
            for (const BoundParameter& parameter : section.parameters)
                QVERIFY2(test::contains(document, "| `" + parameter.declaration.key + "` |"),
                         parameter.declaration.key.c_str());
        }
    }

    void exampleIsValid() {
        const Scene example = sceneFromText(sceneToText(sceneFormatExample()), "example");
        QVERIFY(!example.obstacles.empty());
        QVERIFY(validateScene(example).empty());
    }
};

AIRTRAP_TEST_APPLESS(TestSceneFormatDoc)
#include "TestSceneFormatDoc.moc"
