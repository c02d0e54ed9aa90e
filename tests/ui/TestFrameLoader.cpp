// The timeline's frame loader: reads frames off the GUI thread, keeps recent ones in a small
// LRU, answers only the newest request, and reports damaged or vanished frames by name.
#include "BakeTestScenes.h"
#include "controller/FrameLoader.h"
#include "controller/FrameLru.h"
#include "controller/LoadRequests.h"
#include "support/WidgetTestMain.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <chrono>
#include <thread>

namespace airtrap {

namespace {

//! A frame whose data weighs about `particles` × 32 bytes.
std::shared_ptr<const FrameData> syntheticFrame(int frame, std::size_t particles) {
    auto data = std::make_shared<FrameData>();
    data->state.frame = frame;
    data->state.fluid.resize(particles);
    return data;
}

std::string stdPath(const QTemporaryDir& dir) {
    return dir.path().toStdString();
}

} // namespace

class TestFrameLoader : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(baked_.isValid());
        test::bakeNow(test::tinyDamBreak(), baked_.path());
    }

    void loadsFramesOffTheGuiThread() {
        FrameLoader loader;
        QSignalSpy listed(&loader, &FrameLoader::framesListed);
        QSignalSpy loaded(&loader, &FrameLoader::frameLoaded);
        bool onGuiThread = false;
        connect(&loader, &FrameLoader::frameLoaded, this,
                [&onGuiThread] { onGuiThread = QThread::currentThread() == qApp->thread(); });
        loader.setCacheDirectory(baked_.path());
        loader.request(3);
        QCOMPARE(loaded.count(), 0); // queued, never answered inside request()
        QVERIFY(loaded.wait(5000));
        QVERIFY(onGuiThread);
        QCOMPARE(loaded.first().at(0).toInt(), 3);
        const auto data = loaded.first().at(1).value<std::shared_ptr<const FrameData>>();
        QVERIFY(data);
        QVERIFY(*data == FrameCache::open(stdPath(baked_)).readFrame(3));
        QTRY_COMPARE(listed.count(), 1);
        QCOMPARE(listed.first().at(0).value<QList<int>>(), QList<int>({1, 2, 3, 4}));
        QCOMPARE(loader.cachedFrames(), std::vector<int>({1, 2, 3, 4}));
    }

    void answersRepeatedRequestsFromMemory() {
        FrameLoader loader;
        QSignalSpy loaded(&loader, &FrameLoader::frameLoaded);
        loader.setCacheDirectory(baked_.path());
        loader.request(2);
        QVERIFY(loaded.wait(5000));
        QCOMPARE(loader.loadsPerformed(), 1);
        loader.request(2);
        QVERIFY(loaded.wait(5000));
        QCOMPARE(loaded.count(), 2);
        QCOMPARE(loader.loadsPerformed(), 1);
        QCOMPARE(loaded.at(0).at(1).value<std::shared_ptr<const FrameData>>(),
                 loaded.at(1).at(1).value<std::shared_ptr<const FrameData>>());
    }

    void lruEvictsTheLeastRecentlyUsed() {
        FrameLru lru(FrameLru::Limits{.maxFrames = 3, .maxBytes = std::size_t(1) << 30});
        for (int frame : {1, 2, 3})
            lru.insert(frame, syntheticFrame(frame, 10));
        QVERIFY(lru.find(1)); // 1 is now the most recent, 2 the oldest
        lru.insert(4, syntheticFrame(4, 10));
        QCOMPARE(lru.frames(), std::vector<int>({4, 1, 3}));
        QVERIFY(!lru.contains(2));
        QVERIFY(!lru.find(2));
        lru.erase(1);
        QCOMPARE(lru.frames(), std::vector<int>({4, 3}));
        QCOMPARE(lru.bytes(), 2 * FrameLru::bytesOf(*syntheticFrame(0, 10)));
    }

    void lruKeepsToItsByteBudget() {
        const std::size_t frameBytes = FrameLru::bytesOf(*syntheticFrame(0, 1000));
        FrameLru lru(FrameLru::Limits{.maxFrames = 8, .maxBytes = 2 * frameBytes + 100});
        for (int frame : {1, 2, 3})
            lru.insert(frame, syntheticFrame(frame, 1000));
        QCOMPARE(lru.frames(), std::vector<int>({3, 2}));
        QVERIFY(lru.bytes() <= lru.limits().maxBytes);
        // A frame larger than the whole budget is still kept: it is the one on screen.
        lru.insert(4, syntheticFrame(4, 100000));
        QCOMPARE(lru.frames(), std::vector<int>({4}));
    }

    void requestsMergeNewestFirst() {
        LoadRequests requests;
        requests.load(2);
        requests.load(3);
        requests.load(4);
        LoadWork work = requests.take();
        QCOMPARE(work.frame.value_or(0), 4);
        QVERIFY(!work.directory && !work.refresh && !work.quit);
        requests.load(5);
        requests.setDirectory("/elsewhere", 7);
        work = requests.take();
        QVERIFY2(!work.frame, "a frame asked of the old folder is dropped");
        QCOMPARE(work.directory.value_or(""), std::string("/elsewhere"));
        QCOMPARE(work.generation, 7);
    }

    void onlyTheNewestRequestIsAnswered() {
        // One frame of memory: every request that is not merged away needs the disk.
        FrameLoader loader(FrameLru::Limits{.maxFrames = 1, .maxBytes = std::size_t(1) << 30});
        QSignalSpy loaded(&loader, &FrameLoader::frameLoaded);
        loader.setCacheDirectory(baked_.path());
        loader.request(2);
        // The GUI thread is busy for a moment (as while handling a drag) without running its
        // event loop: the loader reads frame 2 meanwhile, and its answer waits in the queue.
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        // As many requests as the scrubbing test makes: a loaded machine that pauses this
        // thread between two requests lets the loader take one in between (9 of 20 under a
        // full CI run), so the bound is a share of many requests, not a handful.
        constexpr int kRequests = 200;
        for (int i = 0; i < kRequests; ++i)
            loader.request(3 + i % 2); // 3, 4, 3, …, 4
        QVERIFY(loaded.wait(5000));
        QTest::qWait(300); // time for any stray answer to arrive
        QCOMPARE(loaded.count(), 1);
        QCOMPARE(loaded.first().at(0).toInt(), 4);
        // The requests made while the loader was busy were merged into the newest; without
        // merging it would read the disk for every one of the 201.
        QVERIFY2(loader.loadsPerformed() < kRequests / 4,
                 qPrintable(QString::number(loader.loadsPerformed())));
    }

    void scrubbingDoesNotQueueALoadPerRequest() {
        // One frame of memory, so that every request would need the disk without merging.
        FrameLoader loader(FrameLru::Limits{.maxFrames = 1, .maxBytes = std::size_t(1) << 30});
        QSignalSpy loaded(&loader, &FrameLoader::frameLoaded);
        loader.setCacheDirectory(baked_.path());
        constexpr int kRequests = 200;
        for (int i = 0; i < kRequests; ++i)
            loader.request(2 + i % 3);
        const int newest = 2 + (kRequests - 1) % 3;
        QVERIFY(loaded.wait(5000));
        QTest::qWait(300);
        QCOMPARE(loaded.count(), 1);
        QCOMPARE(loaded.first().at(0).toInt(), newest);
        QVERIFY2(loader.loadsPerformed() < kRequests / 4,
                 qPrintable(QStringLiteral("%1 loads").arg(loader.loadsPerformed())));
    }

    void damagedFrameIsReportedByName() {
        QTemporaryDir dir;
        QVERIFY(test::copyCache(baked_.path(), dir.path()));
        QFile frame(dir.filePath(QStringLiteral("frame_0003.atf")));
        QVERIFY(frame.open(QIODevice::ReadWrite));
        QVERIFY(frame.seek(frame.size() / 2));
        frame.write(QByteArray(64, '\x5a'));
        frame.close();

        FrameLoader loader;
        QSignalSpy loaded(&loader, &FrameLoader::frameLoaded);
        QSignalSpy failedLoads(&loader, &FrameLoader::loadFailed);
        loader.setCacheDirectory(dir.path());
        loader.request(3);
        QVERIFY(failedLoads.wait(5000));
        QCOMPARE(failedLoads.first().at(0).toInt(), 3);
        const QString message = failedLoads.first().at(1).toString();
        QVERIFY2(message.contains(QStringLiteral("frame_0003.atf")), qPrintable(message));
        loader.request(2);
        QVERIFY(loaded.wait(5000));
        QCOMPARE(loaded.first().at(0).toInt(), 2);
    }

    void frameDroppedByADiscardIsReportedAfterReloading() {
        QTemporaryDir dir;
        QVERIFY(test::copyCache(baked_.path(), dir.path()));
        FrameLoader loader;
        QSignalSpy loaded(&loader, &FrameLoader::frameLoaded);
        QSignalSpy failedLoads(&loader, &FrameLoader::loadFailed);
        QSignalSpy listed(&loader, &FrameLoader::framesListed);
        loader.setCacheDirectory(dir.path());
        loader.request(4);
        QVERIFY(loaded.wait(5000));

        // Another FrameCache object (the bake controller's) drops frames 3 and 4.
        FrameCache::open(stdPath(dir)).truncateAfter(2);
        loader.request(3);
        QVERIFY(failedLoads.wait(5000));
        const QString message = failedLoads.first().at(1).toString();
        QVERIFY2(message.contains(QStringLiteral("no longer")), qPrintable(message));
        QTRY_COMPARE(listed.last().at(0).value<QList<int>>(), QList<int>({1, 2}));

        // Frame 4 was in memory; the reload found it gone and dropped it there too.
        loader.request(4);
        QVERIFY(failedLoads.wait(5000));
        QCOMPARE(failedLoads.last().at(0).toInt(), 4);
    }

    void folderWithoutACacheYetListsNothingUntilRefreshed() {
        QTemporaryDir dir;
        FrameLoader loader;
        QSignalSpy loaded(&loader, &FrameLoader::frameLoaded);
        QSignalSpy failedLoads(&loader, &FrameLoader::loadFailed);
        QSignalSpy listed(&loader, &FrameLoader::framesListed);
        loader.setCacheDirectory(dir.path());
        QVERIFY(listed.wait(5000));
        QVERIFY(listed.first().at(0).value<QList<int>>().isEmpty());
        loader.request(1);
        QVERIFY(failedLoads.wait(5000));
        QVERIFY(
            failedLoads.first().at(1).toString().contains(QStringLiteral("not an Airtrap cache")));

        QVERIFY(test::copyCache(baked_.path(), dir.path()));
        loader.refresh();
        QVERIFY(listed.wait(5000));
        QCOMPARE(listed.last().at(0).value<QList<int>>(), QList<int>({1, 2, 3, 4}));
        loader.request(1);
        QVERIFY(loaded.wait(5000));
    }

    void answersForALeftFolderAreDropped() {
        QTemporaryDir empty;
        FrameLoader loader;
        QSignalSpy loaded(&loader, &FrameLoader::frameLoaded);
        QSignalSpy failedLoads(&loader, &FrameLoader::loadFailed);
        loader.setCacheDirectory(baked_.path());
        loader.request(2);
        loader.setCacheDirectory(empty.path());
        QTest::qWait(300);
        QCOMPARE(loaded.count(), 0);
        QCOMPARE(failedLoads.count(), 0);
        QVERIFY(loader.cachedFrames().empty());
    }

private:
    QTemporaryDir baked_;
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestFrameLoader)
#include "TestFrameLoader.moc"
