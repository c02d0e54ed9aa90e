// airtrap-cli end to end, validate, bake and info: run as a process on a tiny scene, checking
// exit codes, messages, the cache left behind, bit-identical resume and damage (docs/CLI.md,
// docs/CACHE_FORMAT.md). post, export and check are TestCliPostExport's; full disks, file-size
// limits, kill -9 and Ctrl-C are the fault tests' (tests/faults).
#include "cache/FrameCache.h"
#include "cli/CliFixture.h"
#include "support/TestMain.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <filesystem>

using namespace airtrap;
using namespace airtrap::clitest;
namespace fs = std::filesystem;

namespace {

//! The state of one cached frame as bytes, without its timing statistics (wall-clock times
//! differ from run to run; the simulated state must not).
std::vector<std::uint8_t> stateBytes(const std::string& cacheDir, int frame) {
    return encodeFrame(FrameCache::open(cacheDir).readFrame(frame).state, FrameStats{});
}

std::vector<int> framesOf(const std::string& cacheDir) {
    return FrameCache::open(cacheDir).frames();
}

//! The alive bubbles the per-frame progress line of `frame` reports ("... 2 bubbles  ETA"),
//! or -1 when that line has no bubble count.
int bubblesOnProgressLine(const QString& err, int frame) {
    const QRegularExpression pattern(
        QStringLiteral("^frame %1/\\d+ .* particles  (\\d+) bubbles  ETA ").arg(frame),
        QRegularExpression::MultilineOption);
    const QRegularExpressionMatch match = pattern.match(err);
    return match.hasMatch() ? match.captured(1).toInt() : -1;
}

std::vector<int> oneTo(int last) {
    std::vector<int> frames;
    for (int frame = 1; frame <= last; ++frame)
        frames.push_back(frame);
    return frames;
}

} // namespace

class TestCli : public QObject, protected CliFixture {
    Q_OBJECT

private Q_SLOTS:
    void init() { setUpFolder(); }
    void cleanup() { tearDownFolder(); }

    void helpListsTheExitCodes() {
        const CliResult result = runCli({"--help"});
        QCOMPARE_EXIT(result, 0);
        for (const char* part : {"validate", "bake", "info", "export", "Exit codes", "130"})
            QVERIFY_CONTAINS(result.out, part);
        QCOMPARE_EXIT(runCli({"bake", "--help"}), 0);
    }

    void usageErrorsExitOne_data() {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("named");
        QTest::newRow("unknown verb") << QStringList{"frobnicate"} << "frobnicate";
        QTest::newRow("no verb") << QStringList{} << "subcommand";
        QTest::newRow("unknown option")
            << QStringList{"bake", "s.json", "--out", "x", "--bogus"} << "--bogus";
        QTest::newRow("missing --out") << QStringList{"bake", "s.json"} << "--out";
        QTest::newRow("bad threads")
            << QStringList{"bake", "s.json", "--out", "x", "-j", "many"} << "threads";
        QTest::newRow("unknown format")
            << QStringList{"export", "c", "--format", "fbx", "--out", "o"} << "fbx";
    }

    void usageErrorsExitOne() {
        QFETCH(QStringList, arguments);
        QFETCH(QString, named);
        const CliResult result = runCli(arguments);
        QCOMPARE_EXIT(result, 1);
        QVERIFY(result.err.startsWith("airtrap-cli: "));
        QVERIFY_CONTAINS(result.err, named.toStdString());
    }

    void validateReportsTheParticleCount() {
        const CliResult result = runCli(args({"validate", scene_}));
        QCOMPARE_EXIT(result, 0);
        QVERIFY_CONTAINS(result.out, "OK: " + scene_ + " (125 particles, 4 frames at 60 fps)");
    }

    void badScenesExitTwoNamingTheProblem_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QStringList>("named");
        const QString valid = QString::fromStdString(tinySceneText(4));
        QTest::newRow("malformed JSON")
            << QString("{\n  \"format_version\": 1,\n  \"name\" 3\n}\n") << QStringList{"line 3"};
        QTest::newRow("out of range")
            << QString(valid).replace("\"particle_spacing\": 0.04", "\"particle_spacing\": 5.0")
            << QStringList{"solver.particle_spacing", "5", "[0.001, 1]"};
        QTest::newRow("unknown key")
            << QString(valid).replace("particle_spacing", "partcle_spacing")
            << QStringList{"partcle_spacing", "particle_spacing"};
    }

    void badScenesExitTwoNamingTheProblem() {
        QFETCH(QString, text);
        QFETCH(QStringList, named);
        const std::string file = writeScene("bad.json", text.toStdString());
        for (const QStringList& arguments :
             {args({"validate", file}), args({"bake", file, "--out", cache_})}) {
            const CliResult result = runCli(arguments);
            QCOMPARE_EXIT(result, 2);
            QVERIFY_CONTAINS(result.err, "airtrap-cli: " + file);
            for (const QString& part : named)
                QVERIFY_CONTAINS(result.err, part.toStdString());
        }
        QVERIFY2(!fs::exists(cache_), "a refused scene must not touch --out");
    }

    void badOverrideExitsTwo() {
        const CliResult result = runCli(args({"validate", scene_, "--set", "solver.cfl_factor=9"}));
        QCOMPARE_EXIT(result, 2);
        QVERIFY_CONTAINS(result.err, "--set: solver.cfl_factor = 9");
    }

    void bakeThenInfoDescribesTheLastFrame() {
        bake(cache_);
        QCOMPARE(framesOf(cache_), oneTo(4));
        QCOMPARE(readJson(cache_ + "/manifest.json").at("status").get<std::string>(),
                 std::string("complete"));
        const CliResult result = runCli(args({"info", cache_, "--json"}));
        QCOMPARE_EXIT(result, 0);
        const nlohmann::json info = nlohmann::json::parse(result.out.toStdString());
        QCOMPARE(info.at("frame").get<int>(), 4);
        QVERIFY(std::abs(info.at("time").get<double>() - 3.0 / 60.0) < 1e-12);
        QVERIFY(info.at("steps").get<std::uint64_t>() > 0);
        const nlohmann::json& fluid = info.at("fluid");
        QCOMPARE(fluid.at("count").get<int>(), 125);
        QCOMPARE(fluid.at("bounds").size(), std::size_t(2));
        // The fastest particle of the cached frame, as the engine reads it back.
        const FrameData last = FrameCache::open(cache_).readFrame(4);
        double fastest = 0.0;
        for (const Vec3f& v : last.state.fluid.velocities)
            fastest = std::max(fastest, double(v.norm()));
        QVERIFY(fastest > 0.1); // the block is falling
        QVERIFY(std::abs(fluid.at("max_speed").get<double>() - fastest) < 1e-6 * fastest);
        QVERIFY(std::abs(fluid.at("mean_density").get<double>() - 1000.0) < 50.0);
        const nlohmann::json& bodies = info.at("bodies");
        QCOMPARE(bodies.size(), std::size_t(1)); // the tank, centred on its 0.3 m cube
        QCOMPARE(bodies[0].at("name").get<std::string>(), std::string("Container"));
        QCOMPARE(bodies[0].at("motion").get<std::string>(), std::string("static"));
        for (int axis = 0; axis < 3; ++axis)
            QVERIFY(std::abs(bodies[0].at("position")[axis].get<double>() - 0.15) < 1e-6);
        QCOMPARE(bodies[0].at("orientation"), nlohmann::json({1.0, 0.0, 0.0, 0.0}));
        QVERIFY(info.at("timing").contains("wall_seconds"));
        QVERIFY(info.at("timing").contains("neighbours"));
        QCOMPARE(info.at("cache").at("frames"), nlohmann::json({1, 2, 3, 4}));
        // Bubbles are off in this scene: none alive, none ever made or deleted.
        const nlohmann::json& bubbles = info.at("bubbles");
        QCOMPARE(bubbles.at("count").get<int>(), 0);
        QCOMPARE(bubbles.at("created_total").get<int>(), 0);
        QCOMPARE(
            bubbles.at("deleted_total"),
            nlohmann::json(
                {{"age", 0}, {"floating", 0}, {"overlap", 0}, {"impact", 0}, {"surfaced", 0}}));
        QCOMPARE(bubbles.at("items"), nlohmann::json::array());

        const CliResult second = runCli(args({"info", cache_, "--frame", "2", "--json"}));
        QCOMPARE_EXIT(second, 0);
        QCOMPARE(nlohmann::json::parse(second.out.toStdString()).at("frame").get<int>(), 2);
        QCOMPARE_EXIT(runCli(args({"info", cache_, "--frame", "9"})), 2);
        QCOMPARE_EXIT(runCli(args({"info", root_})), 2); // not a cache
    }

    void infoReportsADivergenceFreeBakesSolves() {
        bake(cache_, {"--set", "solver.method=dfsph"});
        const CliResult result = runCli(args({"info", cache_, "--json"}));
        QCOMPARE_EXIT(result, 0);
        const nlohmann::json solve =
            nlohmann::json::parse(result.out.toStdString()).at("pressure_solve");
        QVERIFY(solve.at("steps").get<int>() >= 1);
        QVERIFY(solve.at("divergence_iterations_per_step").get<double>() >= 2.0);
        QVERIFY(solve.at("density_iterations_per_step").get<double>() >= 2.0);
        QVERIFY(solve.at("max_density_error").get<double>() <= 0.0001);
        QCOMPARE(solve.at("unconverged_steps").get<int>(), 0);
        QVERIFY_CONTAINS(runCli(args({"info", cache_})).out, "solver  DFSPH, ");
        // A WCSPH bake's frames have no such block.
        const std::string wcsph = cache_ + "_wcsph";
        bake(wcsph);
        const CliResult other = runCli(args({"info", wcsph, "--json"}));
        QVERIFY(!nlohmann::json::parse(other.out.toStdString()).contains("pressure_solve"));
    }

    void infoReportsTheFramesBubbles() {
        bake(cache_);
        // Bubbles written into frame 4 as a bake with bubbles would leave them: two alive, five
        // made so far, three deleted (one of them, by the floating rule, during frame 4).
        FrameCache cache = FrameCache::open(cache_);
        FrameData frame = cache.readFrame(4);
        frame.state.bubbles = {bubbleAt(3, Vec3d(0.1, 0.08, 0.12), 0.02, Vec3d(0, 0.05, 0), 0.03),
                               bubbleAt(4, Vec3d(0.05, 0.1, 0.1), 0.015, Vec3d(0.01, 0, 0), 0.0)};
        frame.state.nextBubbleId = 5;
        frame.state.bubblesDeleted.deleted = {1, 1, 0, 1, 0};
        frame.stats.bubbles.created = 1;
        frame.stats.bubbles.deleted = {0, 1, 0, 0, 0};
        cache.writeFrame(frame.state, frame.stats);

        const CliResult result = runCli(args({"info", cache_, "--json"}));
        QCOMPARE_EXIT(result, 0);
        const nlohmann::json bubbles =
            nlohmann::json::parse(result.out.toStdString()).at("bubbles");
        QCOMPARE(bubbles.at("count").get<int>(), 2);
        QCOMPARE(bubbles.at("created_total").get<int>(), 5);
        QCOMPARE(
            bubbles.at("deleted_total"),
            nlohmann::json(
                {{"age", 1}, {"floating", 1}, {"overlap", 0}, {"impact", 1}, {"surfaced", 0}}));
        QCOMPARE(bubbles.at("created_in_frame").get<int>(), 1);
        QCOMPARE(
            bubbles.at("deleted_in_frame"),
            nlohmann::json(
                {{"age", 0}, {"floating", 1}, {"overlap", 0}, {"impact", 0}, {"surfaced", 0}}));
        const nlohmann::json& items = bubbles.at("items");
        QCOMPARE(items.size(), std::size_t(2));
        QCOMPARE(items[0].at("id").get<int>(), 3);
        QCOMPARE(items[0].at("center"), nlohmann::json({0.1, 0.08, 0.12}));
        QCOMPARE(items[0].at("radius").get<double>(), 0.02);
        QCOMPARE(items[0].at("velocity"), nlohmann::json({0.0, 0.05, 0.0}));
        QCOMPARE(items[0].at("age").get<double>(), 0.03);
        QCOMPARE(items[1].at("id").get<int>(), 4);
        QCOMPARE(items[1].at("center"), nlohmann::json({0.05, 0.1, 0.1}));
        QCOMPARE(items[1].at("radius").get<double>(), 0.015);

        const CliResult text = runCli(args({"info", cache_}));
        QCOMPARE_EXIT(text, 0);
        QVERIFY_CONTAINS(text.out, "bubbles 2 alive, 5 created, 3 deleted "
                                   "(age 1, floating 1, overlap 0, impact 1, surfaced 0)");
    }

    void progressLineCountsTheAliveBubbles() {
        const std::string scene = writeScene("bubbles.json", tinyBubbleSceneText(4));
        QCOMPARE_EXIT(runCli(args({"bake", scene, "--out", cache_, "--frames", ":2"})), 0);
        // Two bubbles in the water at the end of frame 2; the bake resumes there.
        FrameCache cache = FrameCache::open(cache_);
        FrameData frame = cache.readFrame(2);
        frame.state.bubbles = {bubbleAt(0, Vec3d(0.07, 0.07, 0.07), 0.03, Vec3d::Zero(), 0.0),
                               bubbleAt(1, Vec3d(0.14, 0.07, 0.14), 0.03, Vec3d::Zero(), 0.0)};
        frame.state.nextBubbleId = 2;
        cache.writeFrame(frame.state, frame.stats);

        const CliResult result = runCli(args({"bake", scene, "--out", cache_, "--resume"}));
        QCOMPARE_EXIT(result, 0);
        // One line per frame (stderr is a pipe), each counting the bubbles its frame ends with.
        cache.reload();
        for (const int done : {3, 4}) {
            const int alive = int(cache.readFrame(done).state.bubbles.size());
            QVERIFY2(bubblesOnProgressLine(result.err, done) == alive,
                     qPrintable(QStringLiteral("frame %1 has %2 bubbles; stderr: %3")
                                    .arg(done)
                                    .arg(alive)
                                    .arg(result.err)));
        }
        QVERIFY2(cache.readFrame(3).state.bubbles.size() > 0, qPrintable(result.err));

        // Without bubbles in the scene the line does not mention them.
        const CliResult plain = runCli(args({"bake", scene_, "--out", path("plain")}));
        QCOMPARE_EXIT(plain, 0);
        QVERIFY_CONTAINS(plain.err, "frame 4/4");
        QVERIFY2(!plain.err.contains("bubbles"), qPrintable(plain.err));
    }

    void existingCacheIsNotClobbered() {
        bake(cache_);
        const auto manifest = readBytes(cache_ + "/manifest.json");
        const CliResult result = runCli(args({"bake", scene_, "--out", cache_}));
        QCOMPARE_EXIT(result, 2);
        QVERIFY_CONTAINS(result.err, cache_);
        QVERIFY_CONTAINS(result.err, "--resume");
        QVERIFY_CONTAINS(result.err, "--overwrite");
        QVERIFY(readBytes(cache_ + "/manifest.json") == manifest);
        bake(cache_, {"--overwrite"});
        QCOMPARE(framesOf(cache_), oneTo(4));
    }

    void resumeOfACompleteCacheHasNothingToDo() {
        bake(cache_);
        const CliResult result = runCli(args({"bake", scene_, "--out", cache_, "--resume"}));
        QCOMPARE_EXIT(result, 0);
        QVERIFY_CONTAINS(result.out, "nothing to do");
        QCOMPARE(framesOf(cache_), oneTo(4));
    }

    void resumeTakesTheSameCommandLineEveryTime() {
        // Starts the bake, continues it, and then has nothing to do: one command line.
        const QStringList same =
            args({"bake", scene_, "--out", cache_, "--frames", "1:3", "--resume"});
        QCOMPARE_EXIT(runCli(same), 0);
        QCOMPARE(framesOf(cache_), oneTo(3));
        const auto frame3 = stateBytes(cache_, 3);
        fs::remove(cache_ + "/frame_0003.atf");
        const CliResult continued = runCli(same);
        QCOMPARE_EXIT(continued, 0);
        QVERIFY_CONTAINS(continued.err, "continuing from frame 2");
        QVERIFY(stateBytes(cache_, 3) == frame3);
        const CliResult done = runCli(same);
        QCOMPARE_EXIT(done, 0);
        QVERIFY_CONTAINS(done.out, "nothing to do");
        // A later start frame does not skip what is missing before it: frame 4 continues 3.
        const CliResult later =
            runCli(args({"bake", scene_, "--out", cache_, "--frames", "4:4", "--resume"}));
        QCOMPARE_EXIT(later, 0);
        QCOMPARE(framesOf(cache_), oneTo(4));
    }

    void resumeRecomputesBitIdentically_data() {
        QTest::addColumn<QString>("damage");
        QTest::newRow("last frame deleted") << "delete";
        QTest::newRow("last frame corrupted") << "corrupt";
        QTest::newRow("restart at frame 3") << "restart";
        QTest::newRow("interior frame corrupted") << "interior";
        QTest::newRow("manifest and last frame lost") << "manifest";
    }

    void resumeRecomputesBitIdentically() {
        QFETCH(QString, damage);
        bake(cache_);
        const auto frame3 = stateBytes(cache_, 3);
        const auto frame4 = stateBytes(cache_, 4);
        const std::string last = cache_ + "/frame_0004.atf";
        QStringList extra = {"--resume"};
        if (damage == "delete") {
            fs::remove(last);
        } else if (damage == "manifest") {
            fs::remove(last);
            fs::remove(cache_ + "/manifest.json");
            const CliResult info = runCli(args({"info", cache_}));
            QCOMPARE_EXIT(info, 2);
            QVERIFY_CONTAINS(info.err, "though the folder holds frame files; `airtrap-cli bake "
                                       "SCENE --out " +
                                           cache_ + " --resume` lists them again");
            const CliResult fresh = runCli(args({"bake", scene_, "--out", cache_}));
            QCOMPARE_EXIT(fresh, 2);
            QVERIFY_CONTAINS(fresh.err, "holds frame files but no manifest.json; continue them "
                                        "with --resume");
        } else if (damage == "corrupt" || damage == "interior") {
            // An interior frame's damage was never noticed: resume saw frame 4 whole and had
            // nothing to do. Now frame 3, which frame 4 continues, and frame 4 are baked again.
            const std::string damaged = damage == "corrupt" ? last : cache_ + "/frame_0003.atf";
            std::vector<std::uint8_t> bytes = readBytes(damaged);
            bytes.at(bytes.size() / 2) ^= 0x10;
            writeBytes(damaged, bytes);
        } else {
            extra = {"--frames", "3:4", "--overwrite"};
        }
        const CliResult result = runCli(args({"bake", scene_, "--out", cache_}) + extra);
        QCOMPARE_EXIT(result, 0);
        if (damage == "manifest")
            QVERIFY_CONTAINS(result.err, "manifest.json was missing: rebuilt from 3 frame file(s)");
        else if (damage == "interior")
            QVERIFY_CONTAINS(result.err, "frame_0003.atf: checksum mismatch in the frame data; it "
                                         "and the 1 frame(s) after it are baked again");
        else if (damage != "restart")
            QVERIFY_CONTAINS(result.err, "frame_0004.atf");
        QCOMPARE(framesOf(cache_), oneTo(4));
        QVERIFY(FrameCache::open(cache_).verify().empty());
        QVERIFY2(stateBytes(cache_, 4) == frame4, "resumed frame 4 differs from the original");
        QVERIFY(stateBytes(cache_, 3) == frame3);
    }

    void framesOptionIsChecked() {
        const CliResult reversed =
            runCli(args({"bake", scene_, "--out", cache_, "--frames", "4:2"}));
        QCOMPARE_EXIT(reversed, 2);
        QVERIFY_CONTAINS(reversed.err, "--frames '4:2'");
        const CliResult beyond = runCli(args({"bake", scene_, "--out", cache_, "--frames", ":9"}));
        QCOMPARE_EXIT(beyond, 2);
        QVERIFY_CONTAINS(beyond.err, "1 to 4");
        // Starting at frame 3 continues a cache; there is none yet.
        QCOMPARE_EXIT(runCli(args({"bake", scene_, "--out", cache_, "--frames", "3:"})), 2);
        QVERIFY(!fs::exists(cache_));
        bake(cache_, {"--frames", ":2"});
        QCOMPARE(framesOf(cache_), oneTo(2));
    }

    void outUnderAFileIsAnIoError() {
        writeText(path("plain"), "not a folder");
        const std::string out = path("plain") + "/cache";
        const CliResult result = runCli(args({"bake", scene_, "--out", out}));
        QCOMPARE_EXIT(result, 4);
        QVERIFY_CONTAINS(result.err, out);
    }

    void blowUpExitsFiveKeepingTheGoodFrames() {
        // A speed of sound of 1 m/s cannot hold the pool up: it compresses beyond
        // solver.max_density_error within the first frame.
        const CliResult result =
            runCli(args({"bake", scene_, "--out", cache_, "--set", "solver.max_speed=0.1"}));
        QCOMPARE_EXIT(result, 5);
        QVERIFY_CONTAINS(result.err, "airtrap-cli: frame 2");
        // Nothing moves fast: the message blames the speed of sound, not a speed not reached.
        QVERIFY_CONTAINS(result.err, "Likely cause: the water moves at ");
        QVERIFY_CONTAINS(result.err, "within solver.max_speed = 0.1 m/s, but the speed of sound it "
                                     "sets (10 × solver.max_speed = 1 m/s) is too low");
        QVERIFY(!result.err.contains("too fast"));
        QCOMPARE(framesOf(cache_), oneTo(1));
        QVERIFY(FrameCache::open(cache_).manifest().status.starts_with("failed"));
    }

    void waterStartingFasterThanMaxSpeedIsRefusedBeforeTheBake() {
        // Water thrown at the floor at 30 m/s with a speed of sound for 2 m/s blew up in frame 2.
        const CliResult result = runCli(args({"bake", scene_, "--out", cache_, "--set",
                                              "fluid_blocks[0].initial_velocity=0,-30,0"}));
        QCOMPARE_EXIT(result, 2);
        QVERIFY_CONTAINS(result.err, "initial_velocity's speed is 30 m/s, above solver.max_speed");
        QVERIFY(!fs::exists(cache_ + "/frame_0001.atf"));
    }

    void frameZeroIsAUsageErrorWithAShortMessage() {
        bake(cache_);
        const CliResult result = runCli(args({"info", cache_, "--frame", "0"}));
        QCOMPARE_EXIT(result, 1);
        QVERIFY_CONTAINS(result.err, "--frame: Value 0 not in range 1 to 2147483647");
        QVERIFY2(result.err.size() < 200, qPrintable(result.err));
    }
};

AIRTRAP_TEST_GUILESS(TestCli)
#include "TestCli.moc"
