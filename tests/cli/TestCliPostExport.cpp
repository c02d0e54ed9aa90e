// airtrap-cli post, export and check run as processes on a tiny scene (docs/CLI.md): what they
// write, what they wait for, what they redo, and damage found and named.
#include "cache/FrameCache.h"
#include "cli/CliFixture.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <filesystem>
#include <limits>

using namespace airtrap;
using namespace airtrap::clitest;
namespace fs = std::filesystem;

class TestCliPostExport : public QObject, protected CliFixture {
    Q_OBJECT

private Q_SLOTS:
    void init() { setUpFolder(); }
    void cleanup() { tearDownFolder(); }

    void exportPlyWritesOneFilePerFrame() {
        bake(cache_);
        const std::string out = path("ply");
        QCOMPARE_EXIT(runCli(args({"export", cache_, "--format", "ply", "--out", out})), 0);
        for (int frame = 1; frame <= 4; ++frame) {
            const std::string file = out + "/particles_000" + std::to_string(frame) + ".ply";
            const std::vector<std::uint8_t> bytes = readBytes(file);
            const std::string text(bytes.begin(), bytes.end());
            QVERIFY2(text.starts_with("ply\nformat binary_little_endian 1.0\n"), file.c_str());
            QVERIFY(text.find("\nelement vertex 125\n") != std::string::npos);
            const std::size_t body = text.find("end_header\n") + 11;
            QCOMPARE(bytes.size() - body, std::size_t(125 * 32));
        }
        const std::string some = path("some");
        QCOMPARE_EXIT(
            runCli(args({"export", cache_, "--format", "ply", "--out", some, "--frames", "2:3"})),
            0);
        // The two frames asked for, and the listing of what the folder holds.
        QCOMPARE(std::distance(fs::directory_iterator(some), fs::directory_iterator()), 3);
        QVERIFY(fs::exists(some + "/particles_0002.ply"));
        const nlohmann::json listing = readJson(some + "/export.json");
        QCOMPARE(listing.at("sequences").at("particles.ply").at("frames"), nlohmann::json({2, 3}));
        QCOMPARE(listing.at("frame_end").get<int>(), 4);
    }

    void chunkedExportsLeaveTheListingToOneLastRun() {
        bake(cache_);
        const std::string out = path("chunks");
        for (const char* frames : {"1:2", "3:4"})
            QCOMPARE_EXIT(runCli(args({"export", cache_, "--format", "ply", "--out", out,
                                       "--frames", frames, "--no-listing"})),
                          0);
        QVERIFY(fs::exists(out + "/particles_0004.ply"));
        QVERIFY(!fs::exists(out + "/export.json"));
        const CliResult listed = runCli(args({"export", cache_, "--format", "ply", "--out", out,
                                              "--frames", "2:4", "--listing-only"}));
        QCOMPARE_EXIT(listed, 0);
        QVERIFY_CONTAINS(listed.out, "listed 3 file(s)");
        const nlohmann::json listing = readJson(out + "/export.json");
        QCOMPARE(listing.at("sequences").at("particles.ply").at("frames"),
                 nlohmann::json({2, 3, 4}));
        QCOMPARE_EXIT(runCli(args({"export", cache_, "--format", "ply", "--out", out,
                                   "--no-listing", "--listing-only"})),
                      1);
    }

    void exportSkipsADamagedFrameAndExitsThree() {
        bake(cache_);
        writeBytes(cache_ + "/frame_0002.atf", {1, 2, 3});
        const std::string out = path("ply");
        const CliResult result = runCli(args({"export", cache_, "--format", "ply", "--out", out}));
        QCOMPARE_EXIT(result, 3);
        QVERIFY_CONTAINS(result.err, "frame_0002.atf");
        QVERIFY(!fs::exists(out + "/particles_0002.ply"));
        for (const char* file :
             {"/particles_0001.ply", "/particles_0003.ply", "/particles_0004.ply"})
            QVERIFY2(fs::exists(out + file), file);
    }

    void objAndVdbWaitForThePostStage() {
        bake(cache_);
        const std::string out = path("out");
        for (const char* format : {"vdb", "obj"}) {
            const CliResult result =
                runCli(args({"export", cache_, "--format", format, "--out", out}));
            QCOMPARE_EXIT(result, 2);
            QVERIFY_CONTAINS(result.err, "frame(s) 1, 2, 3, 4 of " + cache_);
            QVERIFY_CONTAINS(result.err, "run `airtrap-cli post " + cache_ + "` first");
            QVERIFY2(!fs::exists(out), "nothing is written when a frame is not ready");
        }
    }

    void postThenExportWritesTheSequences() {
        bake(cache_);
        const CliResult post = runCli(args({"post", cache_}));
        QCOMPARE_EXIT(post, 0);
        QVERIFY_CONTAINS(post.out, "post: 4 frame(s) made");
        const nlohmann::json listed = readJson(cache_ + "/post/post.json");
        QCOMPARE(listed["frames"].size(), std::size_t(4));
        QCOMPARE(listed["settings"]["surface_mesh"]["smoothing"].get<int>(), 4);

        const std::string out = path("out");
        QCOMPARE_EXIT(runCli(args({"export", cache_, "--format", "obj", "--out", out})), 0);
        QCOMPARE_EXIT(
            runCli(args({"export", cache_, "--format", "vdb", "--out", out, "--up", "z"})), 0);
        for (int frame = 1; frame <= 4; ++frame) {
            const std::string digits = "000" + std::to_string(frame);
            const std::vector<std::uint8_t> obj = readBytes(out + "/water_" + digits + ".obj");
            const std::string text(obj.begin(), obj.end());
            QVERIFY(text.starts_with("# Airtrap "));
            QVERIFY(text.find("# water mesh: free_surface") != std::string::npos);
            QVERIFY(text.find("\no water\nv ") != std::string::npos);
            QVERIFY(fs::file_size(out + "/fluid_" + digits + ".vdb") > 0);
        }
        // One listing for both runs, each sequence with its own axes.
        const nlohmann::json listing = readJson(out + "/export.json");
        QCOMPARE(listing.at("sequences").at("water.obj").at("frames"),
                 nlohmann::json({1, 2, 3, 4}));
        QCOMPARE(listing.at("sequences").at("water.obj").at("up_axis").get<std::string>(),
                 std::string("y"));
        QCOMPARE(listing.at("sequences").at("fluid.vdb").at("up_axis").get<std::string>(),
                 std::string("z"));
        QCOMPARE(listing.at("sequences").at("fluid.vdb").at("pattern").get<std::string>(),
                 std::string("fluid_####.vdb"));
        // The closed mode, posted again, says so in the file it writes.
        QCOMPARE_EXIT(runCli(args({"post", cache_, "--set", "surface_mesh.mode=closed"})), 0);
        const std::string closed = path("closed");
        QCOMPARE_EXIT(runCli(args({"export", cache_, "--format", "obj", "--out", closed, "--set",
                                   "surface_mesh.mode=closed"})),
                      0);
        const std::vector<std::uint8_t> obj = readBytes(closed + "/water_0001.obj");
        QVERIFY(std::string(obj.begin(), obj.end()).find("# water mesh: closed") !=
                std::string::npos);
        // The tiny scene has no bubbles and no bodies: no empty sequences for them.
        QVERIFY(!fs::exists(out + "/bubbles_0001.obj"));
        QVERIFY(!fs::exists(out + "/bodies_0001.obj"));
    }

    void postRedoesOnlyWhatChanged() {
        bake(cache_);
        QCOMPARE_EXIT(runCli(args({"post", cache_, "--frames", "1:2"})), 0);
        const CliResult again = runCli(args({"post", cache_}));
        QCOMPARE_EXIT(again, 0);
        QVERIFY_CONTAINS(again.out, "post: 2 frame(s) made, 2 already current");
        const CliResult smoother =
            runCli(args({"post", cache_, "--set", "surface_mesh.smoothing=8"}));
        QCOMPARE_EXIT(smoother, 0);
        QVERIFY_CONTAINS(smoother.out, "post: 4 frame(s) made");
        const CliResult physics = runCli(args({"post", cache_, "--set", "solver.cfl_factor=0.2"}));
        QCOMPARE_EXIT(physics, 2);
        QVERIFY_CONTAINS(physics.err, "--set solver.cfl_factor=0.2: only the render settings");
    }

    void postShedsSubgridBubblesThatExportWith() {
        const std::string scene = writeScene("bubbles.json", tinyBubbleSceneText(4));
        QCOMPARE_EXIT(runCli(args({"bake", scene, "--out", cache_})), 0);
        // A bubble born in frame 3 inside the water, entirely in air at its birth: it sheds the
        // most, and those of its sub-grid bubbles that lie in water stay.
        FrameCache cache = FrameCache::open(cache_);
        for (int number = 3; number <= 4; ++number) {
            FrameData frame = cache.readFrame(number);
            BubbleState bubble = bubbleAt(0, Vec3d(0.1, 0.07, 0.1), 0.02, Vec3d::Zero(), 0.0);
            bubble.areaFractionInWater = 0.0;
            frame.state.bubbles = {bubble};
            frame.state.nextBubbleId = 1;
            cache.writeFrame(frame.state, frame.stats);
        }
        const CliResult post = runCli(args({"post", cache_}));
        QCOMPARE_EXIT(post, 0);
        const nlohmann::json listed = readJson(cache_ + "/post/subgrid.json");
        QCOMPARE(listed["frames"].size(), std::size_t(4));
        const int shed = listed["frames"][2]["bubbles"].get<int>();
        QVERIFY2(shed > 0 && shed <= 24, qPrintable(QString::number(shed)));
        QCOMPARE(listed["frames"][1]["bubbles"].get<int>(), 0);
        const int kept = listed["frames"][3]["bubbles"].get<int>();
        QVERIFY_CONTAINS(post.out, "sub-grid bubbles: 4 frame(s) made; " + std::to_string(kept) +
                                       " in frame 4");

        const std::string out = path("out");
        QCOMPARE_EXIT(runCli(args({"export", cache_, "--format", "ply", "--out", out})), 0);
        const std::vector<std::uint8_t> ply = readBytes(out + "/subgrid_0003.ply");
        const std::string header(ply.begin(), ply.end());
        QVERIFY(header.find("\nelement vertex " + std::to_string(shed) + "\n") !=
                std::string::npos);
        QCOMPARE_EXIT(runCli(args({"export", cache_, "--format", "obj", "--out", out})), 0);
        const std::vector<std::uint8_t> obj = readBytes(out + "/subgrid_0003.obj");
        const std::string text(obj.begin(), obj.end());
        QVERIFY(text.find("\no subgrid_bubbles\n") != std::string::npos);
        std::size_t vertices = 0;
        for (std::size_t at = text.find("\nv "); at != std::string::npos;
             at = text.find("\nv ", at + 1))
            ++vertices;
        QCOMPARE(vertices, std::size_t(42 * shed)); // a once-subdivided icosahedron each

        const CliResult fewer =
            runCli(args({"post", cache_, "--set", "subgrid_bubbles.max_per_bubble=0"}));
        QCOMPARE_EXIT(fewer, 0);
        QVERIFY_CONTAINS(fewer.out, "post: 0 frame(s) made, 4 already current");
        QVERIFY_CONTAINS(fewer.out, "sub-grid bubbles: 4 frame(s) made; 0 in frame 4");
    }

    void framesWithImpossibleValuesAreRefusedByEveryReader() {
        bake(cache_);
        // Written through the cache, so that every checksum holds and only the values are wrong.
        FrameCache cache = FrameCache::open(cache_);
        FrameData notANumber = cache.readFrame(2);
        notANumber.state.fluid.positions[5].y() = std::numeric_limits<float>::quiet_NaN();
        cache.writeFrame(notANumber.state, notANumber.stats);
        FrameData faraway = cache.readFrame(3);
        faraway.state.fluid.positions[7].x() = 1e30f;
        cache.writeFrame(faraway.state, faraway.stats);

        const std::string frame2 = cache_ + "/frame_0002.atf";
        const std::string frame3 = cache_ + "/frame_0003.atf";
        const CliResult info = runCli(args({"info", cache_, "--frame", "2"}));
        QCOMPARE_EXIT(info, 3);
        QVERIFY_CONTAINS(info.err, frame2 +
                                       ": attribute 'positions' of particle 5 (component 1) is "
                                       "nan, expected a finite number");
        const CliResult far = runCli(args({"info", cache_, "--frame", "3"}));
        QCOMPARE_EXIT(far, 3);
        QVERIFY_CONTAINS(far.err, frame3 + ": particle 7 at (1e+30, ");
        QVERIFY_CONTAINS(far.err, "lies outside the scene's domain, expected within");
        const CliResult ply =
            runCli(args({"export", cache_, "--format", "ply", "--out", path("ply")}));
        QCOMPARE_EXIT(ply, 3);
        QVERIFY_CONTAINS(ply.err, frame2);
        QVERIFY_CONTAINS(ply.err, frame3);
        for (const int threads : {1, 2}) {
            const CliResult post =
                runCli(args({"post", cache_, "--threads", std::to_string(threads)}));
            QCOMPARE_EXIT(post, 3);
            QVERIFY_CONTAINS(post.err, frame2);
            QVERIFY_CONTAINS(post.err, frame3);
            QVERIFY(fs::exists(cache_ + "/post/water_0004.atm"));
        }
    }

    void checkFindsEveryDamageAndTheWaysOnRepairIt() {
        bake(cache_);
        QCOMPARE_EXIT(runCli(args({"post", cache_})), 0);
        const CliResult intact = runCli(args({"check", cache_}));
        QCOMPARE_EXIT(intact, 0);
        QVERIFY_CONTAINS(intact.out, "cache frames: 4 verified, 0 damaged");
        QVERIFY_CONTAINS(intact.out, "is intact");

        const auto flip = [](const std::string& file) {
            std::vector<std::uint8_t> bytes = readBytes(file);
            bytes.at(bytes.size() / 2) ^= 0x40;
            writeBytes(file, bytes);
        };
        flip(cache_ + "/frame_0002.atf");
        flip(cache_ + "/post/subgrid_0003.atb");
        const std::vector<std::uint8_t> list = readBytes(cache_ + "/post/post.json");
        writeBytes(cache_ + "/post/post.json", {list.begin(), list.begin() + 40});
        const CliResult damaged = runCli(args({"check", cache_}));
        QCOMPARE_EXIT(damaged, 3);
        QVERIFY_CONTAINS(damaged.out, "damaged: " + cache_ + "/frame_0002.atf");
        QVERIFY_CONTAINS(damaged.out, "damaged: " + cache_ + "/post/post.json");
        QVERIFY_CONTAINS(damaged.out, "damaged: " + cache_ + "/post/subgrid_0003.atb");
        QVERIFY_CONTAINS(damaged.out, "--resume");
        QVERIFY_CONTAINS(damaged.out, "run `airtrap-cli post " + cache_ + "`");

        // A cut-short post.json no longer stops an export that does not need it.
        const CliResult ply =
            runCli(args({"export", cache_, "--format", "ply", "--out", path("ply")}));
        QCOMPARE_EXIT(ply, 3); // frame 2, damaged, is skipped and named
        QVERIFY(fs::exists(path("ply") + "/particles_0004.ply"));

        // The ways on the check names, each with its own command line.
        QCOMPARE_EXIT(runCli(args({"bake", scene_, "--out", cache_, "--resume"})), 0);
        const CliResult post = runCli(args({"post", cache_}));
        QCOMPARE_EXIT(post, 0);
        QVERIFY_CONTAINS(post.err, cache_ + "/post/post.json");
        QVERIFY_CONTAINS(post.err, "started afresh");
        QCOMPARE_EXIT(runCli(args({"check", cache_})), 0);
    }

    void aDamagedPostResultIsNamed() {
        bake(cache_);
        QCOMPARE_EXIT(runCli(args({"post", cache_})), 0);
        writeBytes(cache_ + "/post/water_0002.atm", {1, 2, 3});
        const CliResult result =
            runCli(args({"export", cache_, "--format", "obj", "--out", path("out")}));
        QCOMPARE_EXIT(result, 2);
        QVERIFY_CONTAINS(result.err, "damaged: " + cache_ + "/post/water_0002.atm");
        QVERIFY_CONTAINS(result.err, "run `airtrap-cli post");
        // post makes the damaged result again instead of counting it current, and the export
        // goes through: the way on that the message promises.
        writeBytes(cache_ + "/post/fluid_0003.vdb", {4, 5, 6});
        const CliResult repaired = runCli(args({"post", cache_}));
        QCOMPARE_EXIT(repaired, 0);
        QVERIFY_CONTAINS(repaired.out, "post: 2 frame(s) made, 2 already current");
        QCOMPARE_EXIT(runCli(args({"export", cache_, "--format", "obj", "--out", path("out")})), 0);
    }
};

AIRTRAP_TEST_GUILESS(TestCliPostExport)
#include "TestCliPostExport.moc"
