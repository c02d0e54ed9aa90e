// The editor as an artist uses it: open every sample, edit and undo, save and reopen, bake a few
// frames on the background thread while the timeline fills, scrub, and answer the question about
// frames baked with old settings.
#include "BakeTestScenes.h"
#include "cache/FrameCache.h"
#include "controller/FrameLoader.h"
#include "controller/SimulationController.h"
#include "document/SceneDocument.h"
#include "model/SceneTreeModel.h"
#include "panels/SceneTreePanel.h"
#include "scene/SceneJson.h"
#include "support/WidgetTestMain.h"
#include "timeline/TimelineWidget.h"
#include "viewport/ViewportWidget.h"
#include "window/EditorActions.h"
#include "window/EditorSettings.h"
#include "window/LogPanel.h"
#include "window/MainWindow.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

namespace airtrap {

namespace {

QString samplePath(const QString& name) {
    return QStringLiteral(AIRTRAP_SOURCE_DIR "/samples/") + name;
}

//! The canonical JSON of a scene, as text QCOMPARE can print.
QString sceneText(const Scene& scene) {
    return QString::fromStdString(sceneToJson(scene).dump());
}

//! The shared tiny dam break, with a few more frames to discard and re-bake.
Scene tinyDamBreak() {
    Scene scene = test::tinyDamBreak();
    scene.frames.endFrame = 6;
    return scene;
}

//! Saves the tiny dam break as tiny.json in `folder` and opens it in `window`, shown and without
//! dialogs.
bool openTinyScene(MainWindow& window, const QTemporaryDir& folder) {
    const QString scenePath = folder.filePath(QStringLiteral("tiny.json"));
    writeSceneFile(tinyDamBreak(), scenePath.toStdString());
    window.setInteractive(false);
    window.show();
    return window.openScene(scenePath);
}

//! Presses `button` on the next message box that opens (the test's answer to a question).
void answerNextMessageBox(QMessageBox::StandardButton button) {
    QTimer::singleShot(0, [button] {
        for (QWidget* widget : QApplication::topLevelWidgets())
            if (auto* box = qobject_cast<QMessageBox*>(widget); box && box->isVisible()) {
                box->button(button)->click();
                return;
            }
        answerNextMessageBox(button); // not open yet: look again on the next turn
    });
}

} // namespace

class TestEditor : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        // The test main's scratch store: start from no saved view options or recent files.
        EditorSettings::store().clear();
    }

    void opensEverySample() {
        const QStringList samples =
            QDir(samplePath(QString())).entryList({QStringLiteral("*.json")}, QDir::Files);
        QVERIFY(samples.size() >= 2);
        for (const QString& sample : samples) {
            MainWindow window;
            window.setInteractive(false);
            QVERIFY2(window.openScene(samplePath(sample)), qPrintable(sample));
            const Scene expected = readSceneFile(samplePath(sample).toStdString());
            QCOMPARE(sceneText(window.document().scene()), sceneText(expected));
            QVERIFY(window.windowTitle().contains(sample));
            QCOMPARE(window.timeline()->lastFrame(), expected.frames.endFrame);
            const SceneTreeModel* tree = window.sceneTree()->model();
            QCOMPARE(tree->rowCount(tree->indexOf(SceneItem::group("fluid_blocks"))),
                     static_cast<int>(expected.fluidBlocks.size()));
        }
    }

    void refusesABrokenSceneAndKeepsTheDocument() {
        QTemporaryDir folder;
        const QString broken = folder.filePath(QStringLiteral("broken.json"));
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format_version": 1, "solver": {"particle_spacing": -1}})");
        file.close();
        MainWindow window;
        window.setInteractive(false);
        QVERIFY(window.openScene(samplePath(QStringLiteral("dam_break.json"))));
        QVERIFY(!window.openScene(broken));
        QVERIFY(window.document().filePath().endsWith(QStringLiteral("dam_break.json")));
    }

    void saveThenOpenIsIdentical() {
        QTemporaryDir folder;
        const QString path = folder.filePath(QStringLiteral("edited.json"));
        MainWindow window;
        window.setInteractive(false);
        QVERIFY(window.openScene(samplePath(QStringLiteral("dam_break.json"))));
        SceneDocument& document = window.document();
        QVERIFY(document.editParameter(SceneItem::sectionItem("solver"), "viscosity_alpha", 0.2)
                    .isEmpty());
        document.addElement("obstacles");
        QVERIFY(document.isModified());
        QVERIFY(window.isWindowModified());

        QVERIFY(window.saveSceneAs(path));
        QVERIFY(!document.isModified());
        QVERIFY(!window.isWindowModified());
        const QString saved = sceneText(document.scene());

        MainWindow reopened;
        reopened.setInteractive(false);
        QVERIFY(reopened.openScene(path));
        QCOMPARE(sceneText(reopened.document().scene()), saved);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll().toStdString(), sceneToText(reopened.document().scene()));
    }

    void unsavedChangesAreOfferedBeforeNew() {
        QTemporaryDir folder;
        const QString path = folder.filePath(QStringLiteral("keep.json"));
        MainWindow window;
        QVERIFY(window.saveSceneAs(path));
        window.document().addElement("fluid_blocks");
        answerNextMessageBox(QMessageBox::Save);
        window.newScene();
        QVERIFY(!window.document().isModified());
        QCOMPARE(readSceneFile(path.toStdString()).fluidBlocks.size(), std::size_t(2));

        window.document().addElement("fluid_blocks");
        answerNextMessageBox(QMessageBox::Cancel);
        window.newScene();
        QVERIFY2(window.document().isModified(), "Cancel must keep the edited scene");
    }

    void bakesWhileTheTimelineFillsAndScrubs() {
        QTemporaryDir folder;
        MainWindow window;
        QVERIFY(openTinyScene(window, folder));
        QCOMPARE(window.cacheDirectory(), folder.filePath(QStringLiteral("tiny.cache")));

        QSignalSpy frames(window.controller(), &SimulationController::frameFinished);
        window.actions().bake->trigger();
        // The bake starts at once on its thread; the actions follow its state.
        QVERIFY(window.controller()->isBusy());
        QVERIFY(!window.actions().bake->isEnabled());
        QVERIFY(window.actions().stop->isEnabled());
        QVERIFY(window.actions().pause->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(frames.count() >= 4, 60000);
        QTRY_VERIFY_WITH_TIMEOUT(!window.controller()->isBusy(), 60000);
        QCOMPARE(window.timeline()->cachedFrames(), (QList<int>{1, 2, 3, 4, 5, 6}));

        QSignalSpy shown(&window, &MainWindow::frameShown);
        window.showFrame(3);
        QTRY_VERIFY_WITH_TIMEOUT(!shown.isEmpty(), 10000);
        QCOMPARE(shown.last().first().toInt(), 3);
    }

    void anUnbakedFrameSaysSoInTheViewport() {
        QTemporaryDir folder;
        MainWindow window;
        QVERIFY(openTinyScene(window, folder));
        window.showFrame(1);
        QCOMPARE(window.viewport()->notice(), QString()); // editing the setup
        window.showFrame(4);
        QCOMPARE(window.viewport()->notice(), QStringLiteral("Frame 4 is not baked yet"));
        window.actions().bake->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!window.controller()->isBusy(), 60000);
        QTRY_COMPARE_WITH_TIMEOUT(window.timeline()->cachedFrames().size(), 6, 10000);
        window.showFrame(4);
        QCOMPARE(window.viewport()->notice(), QString());
    }

    //! A mesh body through the whole editor path: the scene's relative mesh path, the bake on
    //! the worker, the bunny's pose in the cached frames.
    void bakesTheDivingBunnySample() {
        QTemporaryDir folder;
        QVERIFY(QDir(folder.path()).mkdir(QStringLiteral("meshes")));
        QVERIFY(QFile::copy(samplePath(QStringLiteral("meshes/bunny_lowres.obj")),
                            folder.filePath(QStringLiteral("meshes/bunny_lowres.obj"))));
        Scene scene = readSceneFile(samplePath(QStringLiteral("diving_bunny.json")).toStdString());
        scene.frames.endFrame = 3;
        const QString scenePath = folder.filePath(QStringLiteral("diving_bunny.json"));
        writeSceneFile(scene, scenePath.toStdString());
        MainWindow window;
        window.setInteractive(false);
        QVERIFY(window.openScene(scenePath));
        window.actions().bake->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!window.controller()->isBusy(), 120000);
        QCOMPARE(window.timeline()->cachedFrames(), (QList<int>{1, 2, 3}));
        const FrameCache cache = FrameCache::open(window.cacheDirectory().toStdString());
        const RigidBodyState first = cache.readFrame(1).state.bodies.at(0);
        const RigidBodyState last = cache.readFrame(3).state.bodies.at(0);
        // Thrown down at 1 m/s under gravity: about 8 cm lower after 2/30 s.
        QVERIFY2(
            first.position.y() - last.position.y() > 0.05,
            qPrintable(QString("the bunny fell %1 m").arg(first.position.y() - last.position.y())));
    }

    void anEngineErrorIsShownWithTheEnginesMessage() {
        QTemporaryDir folder;
        const QString blocker = folder.filePath(QStringLiteral("file"));
        QFile file(blocker);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.close();
        const QString scenePath = folder.filePath(QStringLiteral("tiny.json"));
        writeSceneFile(tinyDamBreak(), scenePath.toStdString());
        MainWindow window;
        window.show();
        QVERIFY(window.openScene(scenePath));
        // A cache folder that cannot exist: its parent is a regular file.
        window.useCacheFolder(blocker + QStringLiteral("/tiny.cache"));
        answerNextMessageBox(QMessageBox::Ok);
        QSignalSpy failed(window.controller(), &SimulationController::failed);
        window.actions().bake->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!failed.isEmpty(), 20000);
        const QString message = failed.first().first().toString();
        QVERIFY2(message.contains(blocker), qPrintable(message));
        QVERIFY(window.log()->toPlainText().contains(message));
        QTRY_VERIFY(!window.controller()->isBusy());
        QVERIFY(window.actions().bake->isEnabled());
    }

    void editingAfterABakeOffersToDiscardLaterFrames() {
        QTemporaryDir folder;
        const QString scenePath = folder.filePath(QStringLiteral("tiny.json"));
        writeSceneFile(tinyDamBreak(), scenePath.toStdString());
        MainWindow window;
        window.show();
        QVERIFY(window.openScene(scenePath));
        window.setInteractive(false);
        window.actions().bake->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(window.timeline()->cachedFrames().size() == 6, 60000);
        QTRY_VERIFY_WITH_TIMEOUT(!window.controller()->isBusy(), 60000);

        window.setInteractive(true);
        window.timeline()->setCurrentFrame(3);
        answerNextMessageBox(QMessageBox::Yes);
        QVERIFY(window.document()
                    .editParameter(SceneItem::sectionItem("solver"), "viscosity_alpha", 0.3)
                    .isEmpty());
        QTRY_COMPARE_WITH_TIMEOUT(window.timeline()->cachedFrames(), (QList<int>{1, 2, 3}), 10000);

        // Resume continues from frame 3 with the edited scene.
        window.actions().resume->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(window.timeline()->cachedFrames().size() == 6, 60000);
        QTRY_VERIFY_WITH_TIMEOUT(!window.controller()->isBusy(), 60000);
        const FrameCache cache = FrameCache::open(window.cacheDirectory().toStdString());
        QCOMPARE(cache.manifest().scene["solver"]["viscosity_alpha"].get<double>(), 0.3);
        QVERIFY(cache.verify().empty());
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestEditor)
#include "TestEditor.moc"
