// The editor's render outputs on their worker thread: Post makes every cached frame's water
// mesh and volume with the document's render settings, an export runs the post stage first and
// then writes the chosen sequences, a cancel keeps what finished, and errors arrive as failed().
#include "BakeTestScenes.h"
#include "controller/RenderOutputController.h"
#include "post/PostStore.h"
#include "support/WidgetTestMain.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>

namespace airtrap {

class TestRenderOutputController : public QObject {
    Q_OBJECT

    QTemporaryDir temp_;
    QString cacheDir_;

    RenderRequest postRequest() const {
        RenderRequest request;
        request.cacheDir = cacheDir_.toStdString();
        return request;
    }

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(temp_.isValid());
        cacheDir_ = temp_.filePath("cache");
        test::bakeNow(test::tinyDamBreak(), cacheDir_);
    }

    void postMakesEveryFrameWithTheDocumentsSettings() {
        RenderOutputController controller;
        QSignalSpy finished(&controller, &RenderOutputController::finished);
        QSignalSpy progress(&controller, &RenderOutputController::progress);
        RenderRequest request = postRequest();
        request.surfaceMesh.smoothing = 2;
        controller.start(request);
        QVERIFY(controller.isBusy());
        QVERIFY(controller.waitForIdle(60000));
        QCOMPARE(finished.count(), 1);
        QVERIFY(finished.at(0).at(0).toBool());
        QVERIFY2(finished.at(0).at(1).toString().startsWith("post: 4 frame(s) made"),
                 qPrintable(finished.at(0).at(1).toString()));
        QVERIFY(!progress.isEmpty());
        QCOMPARE(progress.last().at(1).toDouble(), 100.0);
        const PostStore store = PostStore::open(cacheDir_.toStdString());
        QCOMPARE(store.frames(), (std::vector<int>{1, 2, 3, 4}));
        QCOMPARE(store.settings()["surface_mesh"]["smoothing"].get<int>(), 2);
    }

    void anExportPostsFirstThenWritesTheSequences() {
        RenderOutputController controller;
        QSignalSpy finished(&controller, &RenderOutputController::finished);
        RenderRequest request = postRequest();
        request.formats = {ExportFormat::Obj, ExportFormat::Vdb};
        request.outDir = temp_.filePath("out").toStdString();
        request.firstFrame = 2;
        request.lastFrame = 3;
        controller.start(request);
        QVERIFY(controller.waitForIdle(60000));
        QCOMPARE(finished.count(), 1);
        const QString summary = finished.at(0).at(1).toString();
        QVERIFY2(summary.contains("obj: 2 file(s)") && summary.contains("vdb: 2 file(s)"),
                 qPrintable(summary));
        for (const char* name :
             {"water_0002.obj", "water_0003.obj", "fluid_0002.vdb", "fluid_0003.vdb"})
            QVERIFY2(std::filesystem::exists(request.outDir + "/" + name), name);
        QVERIFY(!std::filesystem::exists(request.outDir + "/water_0004.obj"));
    }

    void aFolderWithoutACacheFails() {
        RenderOutputController controller;
        QSignalSpy failed(&controller, &RenderOutputController::failed);
        RenderRequest request;
        request.cacheDir = temp_.filePath("nothing").toStdString();
        controller.start(request);
        QVERIFY(controller.waitForIdle(60000));
        QCOMPARE(failed.count(), 1);
        QVERIFY2(failed.at(0).at(0).toString().contains("not an Airtrap cache"),
                 qPrintable(failed.at(0).at(0).toString()));
        QVERIFY(!controller.isBusy());
    }

    void aStoppedJobEndsStoppedAndKeepsWhatFinished() {
        // The job itself, stopped before it starts: the controller's cancel() only forwards to
        // it, and a race with a job that finishes first would make this test flaky.
        RenderRequest request = postRequest();
        request.surfaceMesh.smoothing = 7; // new settings: every frame would be made again
        RenderJob job(request, {});
        job.stop();
        const RenderResult result = job.run();
        QCOMPARE(int(result.outcome), int(RenderResult::Outcome::Stopped));
        QVERIFY(PostStore::open(cacheDir_.toStdString()).frames().empty());
        RenderOutputController idle;
        idle.cancel(); // nothing to cancel: harmless
        QVERIFY(!idle.isBusy());
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestRenderOutputController)
#include "TestRenderOutputController.moc"
