// export.json, the listing an importer reads (io/ExportListing.h): one entry per sequence with
// its pattern, frames, axes and each file's CRC-32; runs into one folder merge; a damaged listing
// is rewritten.
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "io/ExportListing.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace airtrap;

class TestExportListing : public QObject {
    Q_OBJECT

    static Scene pouring() {
        Scene scene;
        scene.name = "pouring";
        scene.frames.fps = 24.0;
        scene.frames.endFrame = 90;
        scene.container.min = Vec3d(0.0, 0.0, 0.0);
        scene.container.max = Vec3d(1.0, 0.5, 2.0);
        return scene;
    }

    static std::vector<int> framesOf(const ExportListing& listing, const std::string& sequence) {
        return listing.json().at("sequences").at(sequence).at("frames").get<std::vector<int>>();
    }

private Q_SLOTS:
    void eachSequenceListsItsPatternFramesAndAxes() {
        ExportListing listing;
        listing.setScene(pouring(), UpAxis::Z);
        listing.addFiles(
            {"water_0001.obj", "bubbles_0001.obj", "water_0002.obj", "water_10000.obj"}, UpAxis::Z);
        const nlohmann::json& json = listing.json();
        QCOMPARE(json.at("format").get<std::string>(), std::string("airtrap-export"));
        QCOMPARE(json.at("scene").get<std::string>(), std::string("pouring"));
        QCOMPARE(json.at("fps").get<double>(), 24.0);
        QCOMPARE(json.at("frame_start").get<int>(), 1);
        QCOMPARE(json.at("frame_end").get<int>(), 90);
        QCOMPARE(json.at("units").get<std::string>(), std::string("m"));
        // The tank from (0, 0, 0) to (1, 0.5, 2), y up, is (0, -2, 0) to (1, 0, 0.5) z up.
        const nlohmann::json& container = json.at("container");
        QCOMPARE(container.at("min").get<std::vector<double>>(), (std::vector<double>{0, -2, 0}));
        QCOMPARE(container.at("max").get<std::vector<double>>(), (std::vector<double>{1, 0, 0.5}));
        QCOMPARE(container.at("up_axis").get<std::string>(), std::string("z"));
        const nlohmann::json& water = json.at("sequences").at("water.obj");
        QCOMPARE(water.at("pattern").get<std::string>(), std::string("water_####.obj"));
        QCOMPARE(water.at("up_axis").get<std::string>(), std::string("z"));
        QCOMPARE(framesOf(listing, "water.obj"), (std::vector<int>{1, 2, 10000}));
        QCOMPARE(framesOf(listing, "bubbles.obj"), (std::vector<int>{1}));
    }

    void namesThatAreNoFrameOfASequenceAreLeftOut() {
        ExportListing listing;
        listing.setScene(pouring(), UpAxis::Y);
        listing.addFiles({"notes.txt", "water.obj", "water_01a2.obj", "export.json"}, UpAxis::Y);
        QVERIFY(listing.json().at("sequences").empty());
    }

    void runsIntoOneFolderMergeAndTheLastAxesWin() {
        QTemporaryDir out;
        const std::string dir = out.path().toStdString();
        ExportListing first = ExportListing::readOrEmpty(dir);
        first.setScene(pouring(), UpAxis::Y);
        first.addFiles({"water_0001.obj", "water_0002.obj", "fluid_0001.vdb"}, UpAxis::Y);
        first.write(dir);

        ExportListing second = ExportListing::readOrEmpty(dir);
        second.setScene(pouring(), UpAxis::Y);
        second.addFiles({"water_0003.obj"}, UpAxis::Y);
        second.addFiles({"fluid_0002.vdb"}, UpAxis::Z);
        second.write(dir);

        const ExportListing read = ExportListing::readOrEmpty(dir);
        QCOMPARE(framesOf(read, "water.obj"), (std::vector<int>{1, 2, 3}));
        // The earlier y-up volume is no longer what the listing describes.
        QCOMPARE(framesOf(read, "fluid.vdb"), (std::vector<int>{2}));
        QCOMPARE(read.json().at("sequences").at("fluid.vdb").at("up_axis").get<std::string>(),
                 std::string("z"));
    }

    void eachFileIsListedWithItsCrc32() {
        QTemporaryDir out;
        const std::string dir = out.path().toStdString();
        AtomicFile::write(dir + "/water_0001.obj", std::string("v 0 0 0\n"));
        AtomicFile::write(dir + "/water_0002.obj", std::string("v 1 0 0\n"));
        ExportListing first = ExportListing::readOrEmpty(dir);
        first.setScene(pouring(), UpAxis::Z);
        first.addFiles({"water_0001.obj", "water_0002.obj"}, UpAxis::Z);
        first.recordChecksums(dir, {"water_0001.obj", "water_0002.obj"});
        first.write(dir);
        // zlib.crc32(b"v 0 0 0\n") and zlib.crc32(b"v 1 0 0\n"), as an importer computes them.
        constexpr std::uint32_t frame1 = 4075698151u;
        const nlohmann::json& listed = first.json()["sequences"]["water.obj"]["crc32"];
        QCOMPARE(listed.at("1").get<std::uint32_t>(), frame1);
        QCOMPARE(listed.at("2").get<std::uint32_t>(), 968025154u);

        // Frame 2 written again by a later run: its new bytes are listed, frame 1's kept.
        AtomicFile::write(dir + "/water_0002.obj", std::string("v 2 0 0\n"));
        ExportListing second = ExportListing::readOrEmpty(dir);
        second.setScene(pouring(), UpAxis::Z);
        second.addFiles({"water_0002.obj"}, UpAxis::Z);
        second.recordChecksums(dir, {"water_0002.obj"});
        const nlohmann::json& relisted = second.json()["sequences"]["water.obj"]["crc32"];
        QCOMPARE(relisted.at("1").get<std::uint32_t>(), frame1);
        QCOMPARE(relisted.at("2").get<std::uint32_t>(), 3206977260u); // zlib.crc32(b"v 2 0 0\n")

        // The other axes replace the sequence: the earlier frames' checksums go with them.
        ExportListing turned = ExportListing::readOrEmpty(dir);
        turned.setScene(pouring(), UpAxis::Y);
        turned.addFiles({"water_0002.obj"}, UpAxis::Y);
        turned.recordChecksums(dir, {"water_0002.obj"});
        QVERIFY(!turned.json()["sequences"]["water.obj"]["crc32"].contains("1"));
    }

    void aFileThatCannotBeReadIsNamed() {
        QTemporaryDir out;
        const std::string dir = out.path().toStdString();
        ExportListing listing;
        listing.setScene(pouring(), UpAxis::Z);
        listing.addFiles({"water_0007.obj"}, UpAxis::Z);
        try {
            listing.recordChecksums(dir, {"water_0007.obj"});
            QFAIL("a missing file was listed");
        } catch (const Error& error) {
            QVERIFY2(std::string(error.what()).find("water_0007.obj") != std::string::npos,
                     error.what());
        }
    }

    void aDamagedOrForeignListingReadsAsEmpty() {
        QTemporaryDir out;
        const std::string dir = out.path().toStdString();
        const std::string path = dir + "/export.json";
        for (const std::string& text : {std::string("{\"format\": \"airtrap-export\", \"vers"),
                                        std::string("{\"format\": \"other\", \"sequences\": {}}"),
                                        std::string("[1, 2, 3]")}) {
            AtomicFile::write(path, text);
            const ExportListing listing = ExportListing::readOrEmpty(dir);
            QVERIFY2(listing.json().empty(), text.c_str());
        }
        QVERIFY(ExportListing::readOrEmpty(dir + "/absent").json().empty());
    }
};

AIRTRAP_TEST_APPLESS(TestExportListing)
#include "TestExportListing.moc"
