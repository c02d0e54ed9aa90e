// Render outputs in the editor as an artist reaches them: Make Render Outputs and Export… wait
// for a cache, run in the background with a progress bar and Cancel in the status bar, use the
// document's Surface mesh settings, and write the chosen sequences; the Export dialog turns its
// choices into a request and refuses an empty one.
#include "BakeTestScenes.h"
#include "controller/RenderOutputController.h"
#include "controller/SimulationController.h"
#include "post/PostStore.h"
#include "support/WidgetTestMain.h"
#include "timeline/TimelineWidget.h"
#include "viewport/ViewportWidget.h"
#include "window/EditorActions.h"
#include "window/ExportDialog.h"
#include "window/MainWindow.h"
#include "window/RenderSession.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QProgressBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>

namespace airtrap {

class TestRenderSession : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void postAndExportFromTheEditor() {
        QTemporaryDir folder;
        const QString scenePath = folder.filePath(QStringLiteral("tiny.json"));
        Scene scene = test::tinyDamBreak();
        scene.surfaceMesh.smoothing = 3;
        writeSceneFile(scene, scenePath.toStdString());
        MainWindow window;
        window.setInteractive(false);
        window.show();
        QVERIFY(window.openScene(scenePath));
        QVERIFY2(!window.actions().post->isEnabled(), "nothing cached yet");
        QVERIFY(!window.actions().exportSequences->isEnabled());

        window.actions().bake->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!window.controller()->isBusy(), 60000);
        QTRY_VERIFY_WITH_TIMEOUT(window.actions().post->isEnabled(), 10000);

        QSignalSpy done(window.renderController(), &RenderOutputController::finished);
        window.actions().post->trigger();
        QVERIFY(window.renderController()->isBusy());
        QVERIFY(!window.actions().post->isEnabled());
        QVERIFY(window.actions().cancelRenderOutputs->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!done.isEmpty(), 60000);
        QTRY_VERIFY(!window.renderSession()->progressBar()->isVisible());
        QVERIFY(done.last().at(0).toBool());
        const PostStore store = PostStore::open(window.cacheDirectory().toStdString());
        QCOMPARE(store.frames(), (std::vector<int>{1, 2, 3, 4}));
        QCOMPARE(store.settings()["surface_mesh"]["smoothing"].get<int>(), 3);
        // The timeline marks the frames that now have render outputs.
        QTRY_COMPARE_WITH_TIMEOUT(window.timeline()->renderOutputFrames(), (QList<int>{1, 2, 3, 4}),
                                  10000);
        // The frame on screen gets its water surface; another frame gets its own.
        // Until frame 3's mesh arrives the last frame's stays on screen: wait for frame 3's own.
        window.showFrame(3);
        const int frame3Triangles = int(store.readFreeSurface(3).triangleCount());
        QVERIFY(frame3Triangles > 0);
        QTRY_COMPARE_WITH_TIMEOUT(window.viewport()->surfaceTriangleCount(), frame3Triangles,
                                  10000);
        window.actions().showSurface->setChecked(false);
        QCOMPARE(window.viewport()->surfaceTriangleCount(), 0);
        window.actions().showSurface->setChecked(true);
        window.actions().opaqueSurface->setChecked(true);
        QCOMPARE(window.viewport()->surfaceOpacity(), 1.0f);
        window.actions().wireframeSurface->setChecked(true);
        QCOMPARE(window.viewport()->surfaceShading(), SurfaceShading::Wireframe);
        window.actions().translucentSurface->setChecked(true);
        QVERIFY(window.viewport()->surfaceOpacity() < 1.0f);

        RenderRequest request;
        request.formats = {ExportFormat::Obj};
        request.outDir = folder.filePath(QStringLiteral("out")).toStdString();
        window.renderSession()->run(request);
        QTRY_VERIFY_WITH_TIMEOUT(done.count() == 2, 60000);
        QVERIFY(std::filesystem::exists(request.outDir + "/water_0004.obj"));
        QVERIFY(window.actions().exportSequences->isEnabled());
    }

    void theExportDialogGathersARequest() {
        ExportDialog dialog(12, QStringLiteral("/tmp/somewhere"));
        QVERIFY(dialog.acceptable());
        dialog.vdbBox()->setChecked(true);
        dialog.plyBox()->setChecked(true);
        dialog.firstFrameBox()->setValue(3);
        dialog.lastFrameBox()->setValue(9);
        dialog.upAxisBox()->setCurrentIndex(1);
        const RenderRequest request = dialog.request();
        QCOMPARE(request.formats.size(), std::size_t(3));
        QCOMPARE(request.outDir, std::string("/tmp/somewhere"));
        QCOMPARE(int(request.up), int(UpAxis::Z));
        QCOMPARE(request.firstFrame, 3);
        QCOMPARE(request.lastFrame, 9);
        for (QCheckBox* box : {dialog.objBox(), dialog.vdbBox(), dialog.plyBox()})
            box->setChecked(false);
        QVERIFY2(!dialog.acceptable(), "no format chosen");
        dialog.objBox()->setChecked(true);
        dialog.folderField()->clear();
        QVERIFY2(!dialog.acceptable(), "no folder");
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestRenderSession)
#include "TestRenderSession.moc"
