// The cache folder: round trip through the manifest, damaged frames named and skipped, resume
// helpers, refusing to clobber, and I/O failures that leave the cache consistent.
#include "cache/FrameCache.h"
#include "core/AtomicFile.h"
#include "support/TestMain.h"
#include "unit/CacheTestData.h"

#include <QTemporaryDir>
#include <QtTest/QtTest>
#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sys/resource.h>
#include <thread>
#include <unistd.h>

using namespace airtrap;
using namespace airtrap::testing;
namespace fs = std::filesystem;

namespace {

const nlohmann::json kScene = {{"name", "Tank"}, {"solver", {{"particle_spacing", 0.02}}}};
const std::string kHash = "sha256:0123abcd";

std::vector<std::uint8_t> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

void flipByte(const std::string& path, std::size_t index) {
    std::vector<std::uint8_t> bytes = readBytes(path);
    bytes.at(index) ^= 0x40;
    writeBytes(path, bytes);
}

std::vector<std::string> temporariesIn(const std::string& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".tmp")
            names.push_back(entry.path().filename().string());
    return names;
}

#define QVERIFY_MESSAGE(text, needle)                                                              \
    QVERIFY2(QString::fromStdString(text).contains(QString::fromStdString(needle)),                \
             qPrintable(QString::fromStdString(std::string(text) + " — lacks: " + (needle))))

} // namespace

class TestFrameCache : public QObject {
    Q_OBJECT

    std::unique_ptr<QTemporaryDir> temp_;
    std::string dir_;

    //! A cache with frames 1–3, each a different random state.
    FrameCache makeCacheWithThreeFrames() {
        FrameCache cache = FrameCache::create(dir_, kScene, kHash, 24.0);
        for (int frame = 1; frame <= 3; ++frame)
            cache.writeFrame(randomState(frame, 50, unsigned(frame)), randomStats(unsigned(frame)));
        return cache;
    }

private Q_SLOTS:
    void init() {
        temp_ = std::make_unique<QTemporaryDir>();
        QVERIFY(temp_->isValid());
        dir_ = temp_->path().toStdString() + "/bake/cache"; // parents created by create()
    }

    void cleanup() {
        if (fs::exists(dir_))
            fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
        temp_.reset();
    }

    void writeOpenReadRoundTrip() {
        makeCacheWithThreeFrames();
        const FrameCache cache = FrameCache::open(dir_);
        QCOMPARE(cache.frames(), (std::vector<int>{1, 2, 3}));
        QVERIFY(cache.hasFrame(2));
        QVERIFY(!cache.hasFrame(4));
        for (int frame = 1; frame <= 3; ++frame) {
            const FrameData data = cache.readFrame(frame);
            QVERIFY(data.state == randomState(frame, 50, unsigned(frame)));
            QVERIFY(data.stats == randomStats(unsigned(frame)));
        }
        const CacheManifest& manifest = cache.manifest();
        QCOMPARE(manifest.scene, kScene);
        QCOMPARE(manifest.parameterHash, kHash);
        QCOMPARE(manifest.fps, 24.0);
        QCOMPARE(manifest.status, std::string("baking"));
        QCOMPARE(manifest.creator, std::string("Airtrap ") + AIRTRAP_VERSION);
        QCOMPARE(manifest.frames.at(1).file, std::string("frame_0002.atf"));
        QCOMPARE(manifest.frames.at(1).bytes, fs::file_size(cache.framePath(2)));
        QVERIFY(temporariesIn(dir_).empty());
    }

    void manifestOnDiskListsFrames() {
        makeCacheWithThreeFrames();
        const auto json = nlohmann::json::parse(readBytes(dir_ + "/manifest.json"));
        QCOMPARE(json.at("format").get<std::string>(), std::string("airtrap-cache"));
        QCOMPARE(json.at("format_version").get<int>(), CacheManifest::kFormatVersion);
        QCOMPARE(json.at("parameter_hash").get<std::string>(), kHash);
        QCOMPARE(json.at("frames").size(), std::size_t(3));
        QCOMPARE(json.at("frames")[2].at("file").get<std::string>(), std::string("frame_0003.atf"));
    }

    void rewritingAFrameReplacesItsEntry() {
        FrameCache cache = makeCacheWithThreeFrames();
        const SimulationState other = randomState(2, 80, 99);
        cache.writeFrame(other, FrameStats{});
        QCOMPARE(cache.frames(), (std::vector<int>{1, 2, 3}));
        QVERIFY(FrameCache::open(dir_).readFrame(2).state == other);
    }

    void statusIsSaved() {
        FrameCache cache = makeCacheWithThreeFrames();
        cache.setStatus("failed: disk full");
        QCOMPARE(FrameCache::open(dir_).manifest().status, std::string("failed: disk full"));
    }

    void corruptMiddleFrameNamedAndSkipped() {
        FrameCache cache = makeCacheWithThreeFrames();
        flipByte(cache.framePath(2), 100);
        const auto error = errorOf([&] { cache.readFrame(2); });
        QVERIFY(error && error->kind() == ErrorKind::CacheCorrupt);
        QVERIFY_MESSAGE(error->what(), cache.framePath(2));
        std::vector<std::string> problems;
        QCOMPARE(cache.lastGoodFrame(&problems), 3); // the newest frame is still whole
        QVERIFY(problems.empty());
        const std::vector<std::string> found = cache.verify();
        QCOMPARE(found.size(), std::size_t(1));
        QVERIFY_MESSAGE(found[0], "frame_0002.atf");
    }

    void resumeContinuesBeforeTheFirstDamagedFrame() {
        FrameCache cache = makeCacheWithThreeFrames();
        QCOMPARE(cache.lastFrameBeforeDamage(), 3);
        flipByte(cache.framePath(2), 100);
        std::vector<std::string> problems;
        QCOMPARE(cache.lastFrameBeforeDamage(&problems), 1);
        QCOMPARE(problems.size(), std::size_t(1));
        QVERIFY_MESSAGE(problems[0], "frame_0002.atf");
        fs::remove(cache.framePath(1));
        QCOMPARE(cache.lastFrameBeforeDamage(), 0);
    }

    void corruptLastFrameSkippedByResume() {
        FrameCache cache = makeCacheWithThreeFrames();
        flipByte(cache.framePath(3), fs::file_size(cache.framePath(3)) - 1);
        std::vector<std::string> problems;
        QCOMPARE(cache.lastGoodFrame(&problems), 2);
        QCOMPARE(problems.size(), std::size_t(1));
        QVERIFY_MESSAGE(problems[0], "frame_0003.atf");
        QVERIFY_MESSAGE(problems[0], "checksum mismatch");
        // Resume: drop the bad frame and bake it again.
        cache.truncateAfter(2);
        cache.writeFrame(randomState(3, 50, 3), randomStats(3));
        QVERIFY(FrameCache::open(dir_).readFrame(3).state == randomState(3, 50, 3));
    }

    void truncatedAndMissingFramesNamed() {
        FrameCache cache = makeCacheWithThreeFrames();
        std::vector<std::uint8_t> bytes = readBytes(cache.framePath(3));
        bytes.resize(bytes.size() / 2);
        writeBytes(cache.framePath(3), bytes);
        auto error = errorOf([&] { cache.readFrame(3); });
        QVERIFY(error && error->kind() == ErrorKind::CacheCorrupt);
        QVERIFY_MESSAGE(error->what(), "frame_0003.atf: truncated: expected");
        fs::remove(cache.framePath(2));
        error = errorOf([&] { cache.readFrame(2); });
        QVERIFY(error && error->kind() == ErrorKind::CacheCorrupt);
        QVERIFY_MESSAGE(error->what(), "frame_0002.atf: missing");
        std::vector<std::string> problems;
        QCOMPARE(cache.lastGoodFrame(&problems), 1);
        QCOMPARE(problems.size(), std::size_t(2));
    }

    void valid_but_swappedFrameFileDetected() {
        FrameCache cache = makeCacheWithThreeFrames();
        fs::copy_file(cache.framePath(1), cache.framePath(2), fs::copy_options::overwrite_existing);
        const auto error = errorOf([&] { cache.readFrame(2); });
        QVERIFY(error && error->kind() == ErrorKind::CacheCorrupt);
        QVERIFY_MESSAGE(error->what(), "frame_0002.atf");
    }

    void noGoodFrameGivesZero() {
        FrameCache cache = FrameCache::create(dir_, kScene, kHash, 24.0);
        QCOMPARE(cache.lastGoodFrame(), 0);
        cache.writeFrame(randomState(1, 5, 1), FrameStats{});
        flipByte(cache.framePath(1), 40);
        QCOMPARE(cache.lastGoodFrame(), 0);
    }

    void truncateAfterDeletesLaterFrames() {
        FrameCache cache = makeCacheWithThreeFrames();
        writeBytes(dir_ + "/frame_0009.atf", {1, 2, 3}); // left by an interrupted write
        cache.truncateAfter(1);
        QCOMPARE(cache.frames(), (std::vector<int>{1}));
        QCOMPARE(FrameCache::open(dir_).frames(), (std::vector<int>{1}));
        QVERIFY(fs::exists(cache.framePath(1)));
        QVERIFY(!fs::exists(cache.framePath(2)));
        QVERIFY(!fs::exists(cache.framePath(3)));
        QVERIFY(!fs::exists(dir_ + "/frame_0009.atf"));
    }

    void createRefusesExistingCache() {
        makeCacheWithThreeFrames();
        writeBytes(dir_ + "/notes.txt", {1});
        writeBytes(dir_ + "/notes.tmp", {1});
        writeBytes(dir_ + "/frame_0002.atf.123-0.tmp", {1});
        const auto error = errorOf([&] { FrameCache::create(dir_, kScene, kHash, 24.0); });
        QVERIFY(error && error->kind() == ErrorKind::InvalidInput);
        QVERIFY_MESSAGE(error->what(), "already holds an Airtrap cache");
        QCOMPARE(FrameCache::open(dir_).frames().size(), std::size_t(3)); // untouched

        const FrameCache fresh = FrameCache::create(dir_, kScene, "other", 30.0, true);
        QVERIFY(fresh.frames().empty());
        QCOMPARE(FrameCache::open(dir_).manifest().parameterHash, std::string("other"));
        QVERIFY(!fs::exists(dir_ + "/frame_0001.atf"));
        QVERIFY(!fs::exists(dir_ + "/frame_0002.atf.123-0.tmp"));
        QVERIFY(fs::exists(dir_ + "/notes.txt")); // not ours: never deleted
        QVERIFY(fs::exists(dir_ + "/notes.tmp"));
    }

    void openWithoutManifest() {
        fs::create_directories(dir_);
        const auto error = errorOf([&] { FrameCache::open(dir_); });
        QVERIFY(error);
        QVERIFY_MESSAGE(error->what(), "not an Airtrap cache: " + dir_ + "/manifest.json missing");
        QVERIFY(!FrameCache::isCache(dir_));
    }

    void malformedManifestNamesField() {
        makeCacheWithThreeFrames();
        auto json = nlohmann::json::parse(readBytes(dir_ + "/manifest.json"));
        json["frames"][1]["bytes"] = "many";
        const std::string text = json.dump();
        writeBytes(dir_ + "/manifest.json", {text.begin(), text.end()});
        auto error = errorOf([&] { FrameCache::open(dir_); });
        QVERIFY(error && error->kind() == ErrorKind::CacheCorrupt);
        QVERIFY_MESSAGE(error->what(), dir_ + "/manifest.json: field 'frames[1].bytes'");

        writeBytes(dir_ + "/manifest.json", {'{', '"'});
        error = errorOf([&] { FrameCache::open(dir_); });
        QVERIFY(error && error->kind() == ErrorKind::CacheCorrupt);
        QVERIFY_MESSAGE(error->what(), "not valid JSON");
    }

    void frameFileMustStayInsideTheFolder() {
        makeCacheWithThreeFrames();
        auto json = nlohmann::json::parse(readBytes(dir_ + "/manifest.json"));
        json["frames"][0]["file"] = "../../victim";
        const std::string text = json.dump();
        writeBytes(dir_ + "/manifest.json", {text.begin(), text.end()});
        const auto error = errorOf([&] { FrameCache::open(dir_); });
        QVERIFY(error && error->kind() == ErrorKind::CacheCorrupt);
        QVERIFY_MESSAGE(error->what(), "frames[0].file");
    }

    void newerManifestVersionNamed() {
        makeCacheWithThreeFrames();
        auto json = nlohmann::json::parse(readBytes(dir_ + "/manifest.json"));
        json["format_version"] = CacheManifest::kFormatVersion + 1;
        const std::string text = json.dump();
        writeBytes(dir_ + "/manifest.json", {text.begin(), text.end()});
        const auto error = errorOf([&] { FrameCache::open(dir_); });
        QVERIFY(error);
        QVERIFY_MESSAGE(error->what(), "newer Airtrap");
    }

    void unknownManifestFieldsKept() {
        makeCacheWithThreeFrames();
        auto json = nlohmann::json::parse(readBytes(dir_ + "/manifest.json"));
        json["added_later"] = {{"x", 1}};
        const std::string text = json.dump();
        writeBytes(dir_ + "/manifest.json", {text.begin(), text.end()});
        FrameCache::open(dir_).setStatus("complete");
        json = nlohmann::json::parse(readBytes(dir_ + "/manifest.json"));
        QCOMPARE(json.at("added_later").at("x").get<int>(), 1);
        QCOMPARE(json.at("status").get<std::string>(), std::string("complete"));
    }

    void pathUnderRegularFileIsIoError() {
        const std::string blocker = temp_->path().toStdString() + "/blocker";
        writeBytes(blocker, {1});
        const auto error =
            errorOf([&] { FrameCache::create(blocker + "/cache", kScene, kHash, 24.0); });
        QVERIFY(error && error->kind() == ErrorKind::Io);
        QVERIFY_MESSAGE(error->what(), blocker + "/cache");
    }

    void unwritableFolderIsIoError() {
        if (::geteuid() == 0)
            QSKIP("running as root: chmod does not stop root from writing, so this test could "
                  "not fail; pathUnderRegularFileIsIoError and failedRenameLeavesNoTemporary "
                  "cover the error path");
        fs::create_directories(dir_);
        fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
        const auto error = errorOf([&] { FrameCache::create(dir_, kScene, kHash, 24.0); });
        QVERIFY(error && error->kind() == ErrorKind::Io);
        QVERIFY_MESSAGE(error->what(), dir_ + "/manifest.json: permission denied");
    }

    void failedRenameLeavesNoTemporary() {
        FrameCache cache = FrameCache::create(dir_, kScene, kHash, 24.0);
        cache.writeFrame(randomState(1, 10, 1), FrameStats{});
        // A folder where frame 2 should go makes rename() fail after the temporary is written.
        fs::create_directories(cache.framePath(2) + "/occupied");
        const auto error = errorOf([&] { cache.writeFrame(randomState(2, 10, 2), FrameStats{}); });
        QVERIFY(error && error->kind() == ErrorKind::Io);
        QVERIFY_MESSAGE(error->what(), cache.framePath(2));
        QVERIFY(temporariesIn(dir_).empty());
        QCOMPARE(FrameCache::open(dir_).frames(), (std::vector<int>{1}));
    }

    void failedWriteMidFileLeavesCacheConsistent() {
        FrameCache cache = FrameCache::create(dir_, kScene, kHash, 24.0);
        cache.writeFrame(randomState(1, 10, 1), FrameStats{});
        cache.writeFrame(randomState(2, 10, 2), FrameStats{});
        const std::vector<std::uint8_t> before = readBytes(cache.framePath(1));
        // A file-size limit makes write() fail part-way, like a full disk (and works as root).
        rlimit old{};
        QVERIFY(::getrlimit(RLIMIT_FSIZE, &old) == 0);
        const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit small = old;
        small.rlim_cur = 4096;
        QVERIFY(::setrlimit(RLIMIT_FSIZE, &small) == 0);
        const auto newFrame =
            errorOf([&] { cache.writeFrame(randomState(3, 2000, 3), FrameStats{}); });
        const auto rewrite =
            errorOf([&] { cache.writeFrame(randomState(2, 2000, 7), FrameStats{}); });
        ::setrlimit(RLIMIT_FSIZE, &old);
        std::signal(SIGXFSZ, oldHandler);
        QVERIFY(newFrame && newFrame->kind() == ErrorKind::Io);
        QVERIFY_MESSAGE(newFrame->what(), cache.framePath(3));
        QVERIFY(rewrite && rewrite->kind() == ErrorKind::Io);
        QVERIFY(temporariesIn(dir_).empty());
        QVERIFY(!fs::exists(cache.framePath(3)));
        // A failed re-write leaves that frame unlisted (never listed with a stale checksum).
        QCOMPARE(FrameCache::open(dir_).frames(), (std::vector<int>{1}));
        QVERIFY(readBytes(cache.framePath(1)) == before);
        QVERIFY(FrameCache::open(dir_).readFrame(1).state == randomState(1, 10, 1));
    }

    void errorMessagesSayWhatToDo() {
        QVERIFY_MESSAGE(AtomicFile::errorMessage("cannot write", "/c/f", ENOSPC),
                        "cannot write /c/f: disk full");
        QVERIFY_MESSAGE(AtomicFile::errorMessage("cannot write", "/c/f", EACCES),
                        "/c/f: permission denied");
    }

    void readerThreadSeesOnlyWholeFrames() {
        FrameCache writer = FrameCache::create(dir_, kScene, kHash, 24.0);
        writer.writeFrame(randomState(1, 200, 1), FrameStats{});
        std::atomic<bool> done{false};
        std::atomic<int> reads{0};
        std::string failure;
        std::thread reader([&] {
            try {
                FrameCache own = FrameCache::open(dir_);
                while (!done.load()) {
                    own.reload();
                    const int newest = own.frames().back();
                    if (own.readFrame(newest).state.fluid.size() != 200)
                        failure = "wrong particle count";
                    ++reads;
                }
            } catch (const std::exception& error) {
                failure = error.what();
            }
        });
        for (int frame = 2; frame <= 20; ++frame)
            writer.writeFrame(randomState(frame, 200, unsigned(frame)), FrameStats{});
        done = true;
        reader.join();
        QVERIFY2(failure.empty(), failure.c_str());
        QVERIFY(reads.load() > 0);
    }

    void sharedObjectIsThreadSafe() {
        FrameCache cache = FrameCache::create(dir_, kScene, kHash, 24.0);
        cache.writeFrame(randomState(1, 100, 1), FrameStats{});
        std::atomic<bool> done{false};
        std::string failure;
        std::thread reader([&] {
            try {
                while (!done.load())
                    cache.readFrame(cache.frames().back());
            } catch (const std::exception& error) {
                failure = error.what();
            }
        });
        for (int frame = 2; frame <= 10; ++frame)
            cache.writeFrame(randomState(frame, 100, unsigned(frame)), FrameStats{});
        cache.setStatus("complete");
        done = true;
        reader.join();
        QVERIFY2(failure.empty(), failure.c_str());
        QCOMPARE(cache.manifestSnapshot().frames.size(), std::size_t(10));
    }
};

AIRTRAP_TEST_APPLESS(TestFrameCache)
#include "TestFrameCache.moc"
