// Every sample bakes to the same bits as the engine recorded in tests/data/sample_checksums.json:
// per frame, the CRC-32 of the frame as the cache encodes it, with the wall-clock timings left
// out (they differ from run to run). A restructuring of the engine that should not change the
// physics must keep these; a change that means to alters them, says why in docs/VALIDATION.md and
// records them again (tests/data/sample_checksums.README.txt tells how).
#include "cache/FrameFile.h"
#include "core/Interrupter.h"
#include "scene/SceneJson.h"
#include "sim/Simulation.h"
#include "support/TestMain.h"

#include <QtTest>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace airtrap;

namespace {

const char* const kChecksumFile = AIRTRAP_SOURCE_DIR "/tests/data/sample_checksums.json";

//! The frame's bytes in the cache's encoding, less what depends on the machine's speed.
std::uint32_t frameChecksum(const SimulationState& state, FrameStats stats) {
    stats.wallSeconds = 0.0;
    stats.phaseSeconds.clear();
    const std::vector<std::uint8_t> bytes = encodeFrame(state, stats);
    return computeCrc32(bytes.data(), bytes.size());
}

//! Checksums of frames 1 to `frames` of `sample` baked at its own settings.
std::vector<std::uint32_t> bakeChecksums(const std::string& sample, int frames) {
    const Scene scene = readSceneFile(std::string(AIRTRAP_SOURCE_DIR "/samples/") + sample);
    Simulation simulation(scene);
    Interrupter never;
    std::vector<std::uint32_t> checksums{
        frameChecksum(simulation.state(), simulation.lastFrameStats())};
    while (simulation.frame() < frames) {
        simulation.advanceFrame(never);
        checksums.push_back(frameChecksum(simulation.state(), simulation.lastFrameStats()));
    }
    return checksums;
}

} // namespace

class TestSampleChecksums : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void samplesBakeToTheRecordedBits_data() {
        QTest::addColumn<QString>("sample");
        std::ifstream in(kChecksumFile);
        QVERIFY2(in, kChecksumFile);
        recorded_ = nlohmann::json::parse(in);
        for (const auto& [sample, entry] : recorded_["samples"].items())
            QTest::newRow(sample.c_str()) << QString::fromStdString(sample);
    }

    void samplesBakeToTheRecordedBits() {
        QFETCH(QString, sample);
        const nlohmann::json& entry = recorded_["samples"][sample.toStdString()];
        const std::vector<std::uint32_t> expected =
            entry["frames"].get<std::vector<std::uint32_t>>();
        const std::vector<std::uint32_t> actual =
            bakeChecksums(sample.toStdString(), int(expected.size()));
        if (std::getenv("AIRTRAP_RECORD_CHECKSUMS") != nullptr) {
            recorded_["samples"][sample.toStdString()]["frames"] = actual;
            std::ofstream(kChecksumFile) << recorded_.dump(2) << '\n';
            QSKIP("recorded");
        }
        QCOMPARE(actual.size(), expected.size());
        for (std::size_t k = 0; k < expected.size(); ++k)
            QVERIFY2(actual[k] == expected[k],
                     qPrintable(QStringLiteral("%1 frame %2: CRC %3, recorded %4")
                                    .arg(sample)
                                    .arg(k + 1)
                                    .arg(actual[k])
                                    .arg(expected[k])));
    }

private:
    nlohmann::json recorded_;
};

AIRTRAP_TEST_APPLESS(TestSampleChecksums)
#include "TestSampleChecksums.moc"
