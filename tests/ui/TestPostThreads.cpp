// Post on two threads, stopped or failing while frames are under way: the paths where OpenVDB's
// work of one frame is cut short while another frame runs. In-process, so that the thread
// sanitizer build (scripts/test.sh --sanitize thread) watches them; the CLI's own Ctrl-C and
// full-disk cases run as child processes in tests/faults.
#include "BakeTestScenes.h"
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "core/ThreadLimit.h"
#include "post/PostStage.h"
#include "post/PostStore.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <QtTest>
#include <atomic>
#include <filesystem>
#include <thread>

namespace airtrap {

namespace {

constexpr int kFrames = 8;

Scene eightFrameDamBreak() {
    Scene scene = test::tinyDamBreak();
    scene.frames.endFrame = kFrames;
    return scene;
}

//! The cache's frames, posted with the cache's own scene.
PostReport postAll(const std::string& cacheDir, Interrupter& interrupter) {
    const FrameCache cache = FrameCache::open(cacheDir);
    PostStage post(cache, sceneFromJson(cache.manifest().scene, cache.manifestPath()));
    return post.run(cache.frames(), interrupter);
}

bool holdsATemporary(const std::string& directory) {
    for (const auto& entry : std::filesystem::directory_iterator(directory))
        if (AtomicFile::isTemporaryName(entry.path().filename().string()))
            return true;
    return false;
}

} // namespace

class TestPostThreads : public QObject {
    Q_OBJECT

    QTemporaryDir temp_;
    std::string bakedDir_;

    //! A fresh copy of the baked cache, without post results.
    std::string freshCache(const QString& name) {
        const QString dir = temp_.filePath(name);
        if (!QDir().mkpath(dir) || !test::copyCache(QString::fromStdString(bakedDir_), dir))
            qFatal("cannot copy the cache to %s", qPrintable(dir));
        return dir.toStdString();
    }

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(temp_.isValid());
        bakedDir_ = temp_.filePath("baked").toStdString();
        test::bakeNow(eightFrameDamBreak(), QString::fromStdString(bakedDir_));
    }

    void aStopFromAnotherThreadKeepsWhatFinished() {
        const std::string dir = freshCache("stopped");
        const ThreadLimit threads(2);
        // Ctrl-C's path: the stop comes from a thread that is not one of post's, as soon as the
        // first frame is done, while the second thread is inside OpenVDB's tools.
        std::atomic<bool> firstFrameDone{false};
        Interrupter interrupter([&](const std::string& stage, double percent) {
            if (stage == "post" && percent > 0.0)
                firstFrameDone.store(true);
        });
        PostReport report;
        std::thread postThread([&] { report = postAll(dir, interrupter); });
        while (!firstFrameDone.load())
            std::this_thread::yield();
        interrupter.requestStop();
        postThread.join();

        QVERIFY(report.stopped);
        QVERIFY2(report.made >= 1 && report.made < kFrames,
                 qPrintable(QString::number(report.made)));
        const PostStore kept = PostStore::open(dir);
        QCOMPARE(int(kept.frames().size()), report.made);
        QVERIFY(!holdsATemporary(kept.directory()));

        Interrupter again;
        const PostReport rest = postAll(dir, again);
        QCOMPARE(rest.alreadyCurrent, report.made);
        QCOMPARE(rest.made + rest.alreadyCurrent, kFrames);
        QVERIFY(!rest.stopped);
    }

    void aFrameThatFailsStopsTheOthersAndKeepsWhatFinished() {
        const std::string dir = freshCache("failing");
        const ThreadLimit threads(2);
        // A folder where frame 5's mesh must go: its write fails (EISDIR) like a full disk
        // would, on one thread, while the other is making another frame.
        const std::string blocked = dir + "/post/water_0005.atm";
        QVERIFY(std::filesystem::create_directories(blocked));
        Interrupter interrupter;
        std::optional<Error> failure;
        try {
            postAll(dir, interrupter);
        } catch (const Error& error) {
            failure = error;
        }
        QVERIFY(failure.has_value());
        QCOMPARE(int(failure->kind()), int(ErrorKind::Io));
        QVERIFY2(std::string(failure->what()).find("water_0005.atm") != std::string::npos,
                 failure->what());
        const PostStore kept = PostStore::open(dir);
        for (const int frame : kept.frames())
            QVERIFY(frame != 5);
        QVERIFY(!holdsATemporary(kept.directory()));

        std::filesystem::remove(blocked);
        Interrupter again;
        const PostReport rest = postAll(dir, again);
        QCOMPARE(rest.made + rest.alreadyCurrent, kFrames);
        QCOMPARE(int(PostStore::open(dir).frames().size()), kFrames);
    }
};

} // namespace airtrap

AIRTRAP_TEST_GUILESS(airtrap::TestPostThreads)
#include "TestPostThreads.moc"
