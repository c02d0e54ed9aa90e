// Rigid bodies in the editor: added per shape from Edit ▸ Add ▸ Body (a mesh only when the
// engine can use its file), picked in the viewport, and the question asked before baking a
// scene whose bodies overlap at t = 0.
#include "BakeTestScenes.h"
#include "controller/SimulationController.h"
#include "document/SceneDocument.h"
#include "panels/BodyAddMenu.h"
#include "panels/SceneTreePanel.h"
#include "scene/SceneJson.h"
#include "sim/BodyBuilder.h"
#include "support/WidgetTestMain.h"
#include "viewport/ViewportWidget.h"
#include "window/EditorActions.h"
#include "window/EditorSettings.h"
#include "window/LogPanel.h"
#include "window/MainWindow.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <functional>

namespace airtrap {

namespace {

const QString kBunny = QStringLiteral(AIRTRAP_SOURCE_DIR "/tests/data/bunny_lowres.obj");

//! On the next message box that opens: keeps its text, then presses the button `choose` picks.
void answerNextMessageBox(std::function<QAbstractButton*(QMessageBox&)> choose, QString* text) {
    QTimer::singleShot(0, [choose, text] {
        for (QWidget* widget : QApplication::topLevelWidgets())
            if (auto* box = qobject_cast<QMessageBox*>(widget); box && box->isVisible()) {
                *text = box->text() + QLatin1Char('\n') + box->informativeText();
                choose(*box)->click();
                return;
            }
        answerNextMessageBox(choose, text); // not open yet: look again on the next turn
    });
}

QAction* addBodyAction(const MainWindow& window, const char* shape) {
    return window.findChild<QAction*>(QStringLiteral("add_bodies_") + QLatin1String(shape));
}

//! A rock placed in the water on purpose (a note, no question) and a boulder sunk into the rock
//! (a warning: contacts would push them apart with a jolt).
Scene sceneWithOverlappingBodies() {
    Scene scene = test::tinyDamBreak();
    RigidBodySettings rock;
    rock.name = "Rock";
    rock.motion = "static";
    rock.position = Vec3d(0.12, 0.15, 0.1);
    rock.size = Vec3d(0.15, 0.15, 0.15);
    scene.bodies.push_back(rock);
    RigidBodySettings boulder = rock;
    boulder.name = "Boulder";
    boulder.position.x() += 0.1;
    scene.bodies.push_back(boulder);
    return scene;
}

} // namespace

class TestBodies : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        // The test main's scratch store: start from no saved view options.
        EditorSettings::store().clear();
    }

    void eachShapeIsAddedAboveTheWaterAndUndone() {
        MainWindow window;
        window.setInteractive(false);
        SceneDocument& document = window.document();
        QVERIFY(!window.findChild<QAction*>(QStringLiteral("add_bodies")));
        const Scene& scene = document.scene();
        for (const char* shape : {"box", "sphere", "cylinder"}) {
            QAction* action = addBodyAction(window, shape);
            QVERIFY2(action, shape);
            action->trigger();
            QCOMPARE(scene.bodies.size(), std::size_t(1));
            const RigidBodySettings& body = scene.bodies[0];
            QCOMPARE(body.shape, std::string(shape));
            QCOMPARE(window.sceneTree()->selectedItem(), SceneItem::elementItem("bodies", 0));
            // Inside the container and above the new scene's water (its top is at 0.5 m).
            const Aabb container{scene.container.min, scene.container.max};
            QVERIFY(container.contains(body.position));
            QVERIFY2(body.position.y() > 0.5, qPrintable(QString::number(body.position.y())));
            document.undoStack()->undo();
            QVERIFY(scene.bodies.empty());
        }
        // A second box gets a name of its own: keyframes find bodies by name.
        addBodyAction(window, "box")->trigger();
        addBodyAction(window, "box")->trigger();
        QCOMPARE(scene.bodies[1].name, std::string("Box 2"));
        QCOMPARE(window.sceneTree()->selectedItem(), SceneItem::elementItem("bodies", 1));
    }

    void aMeshBodyStoresItsFileRelativeToTheSavedScene() {
        QTemporaryDir folder;
        MainWindow window;
        window.setInteractive(false);
        QVERIFY(window.saveSceneAs(folder.filePath(QStringLiteral("scene.json"))));
        window.sceneTree()->bodyMenu()->setMeshFileChooser([] { return kBunny; });
        addBodyAction(window, "mesh")->trigger();
        const Scene& scene = window.document().scene();
        QCOMPARE(scene.bodies.size(), std::size_t(1));
        const RigidBodySettings& body = scene.bodies[0];
        QCOMPARE(body.shape, std::string("mesh"));
        QCOMPARE(body.name, std::string("bunny_lowres"));
        QVERIFY(QFileInfo(QString::fromStdString(body.mesh)).isRelative());
        QCOMPARE(QFileInfo(QString::fromStdString(BodyBuilder::meshPath(scene, body)))
                     .canonicalFilePath(),
                 QFileInfo(kBunny).canonicalFilePath());
        QCOMPARE(window.sceneTree()->selectedItem(), SceneItem::elementItem("bodies", 0));
        // The mesh's middle sits where a box's would: over the container's centre.
        const Aabb bounds = BodyBuilder::loadMesh(scene, body).bounds();
        const Vec3d middle = body.position + bounds.center();
        QVERIFY(std::abs(middle.x() - 0.5) < 1e-9 && std::abs(middle.z() - 0.5) < 1e-9);

        // An unsaved scene has no folder to be relative to.
        window.newScene();
        window.sceneTree()->bodyMenu()->addMesh(kBunny);
        QVERIFY(QFileInfo(QString::fromStdString(window.document().scene().bodies.at(0).mesh))
                    .isAbsolute());
    }

    void aMeshThatIsNotClosedIsRefusedWithTheEnginesReason() {
        QTemporaryDir folder;
        const QString open = folder.filePath(QStringLiteral("triangle.obj"));
        QFile file(open);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        file.close();
        MainWindow window;
        window.sceneTree()->bodyMenu()->setMeshFileChooser([open] { return open; });
        QString shown;
        answerNextMessageBox([](QMessageBox& box) { return box.button(QMessageBox::Ok); }, &shown);
        addBodyAction(window, "mesh")->trigger();
        QVERIFY2(shown.contains(QStringLiteral("triangle.obj")), qPrintable(shown));
        QVERIFY2(shown.contains(QStringLiteral("not closed")), qPrintable(shown));
        QVERIFY(window.document().scene().bodies.empty());
        QVERIFY(!window.document().isModified());
        QVERIFY(window.log()->toPlainText().contains(QStringLiteral("not closed")));

        // Unreadable: no such file.
        window.setInteractive(false);
        window.sceneTree()->bodyMenu()->addMesh(folder.filePath(QStringLiteral("missing.obj")));
        QVERIFY(window.document().scene().bodies.empty());
        QVERIFY2(window.lastError().contains(QStringLiteral("missing.obj")),
                 qPrintable(window.lastError()));
    }

    void clickingABodySelectsIt() {
        MainWindow window;
        window.setInteractive(false);
        window.resize(1200, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        addBodyAction(window, "sphere")->trigger();
        window.sceneTree()->selectItem(SceneItem::sectionItem("solver"));
        ViewportWidget* viewport = window.viewport();
        viewport->frameAll();
        const Vec3d centre = window.document().scene().bodies.at(0).position;
        const QPointF spot = viewport->camera().project(
            QVector3D(float(centre.x()), float(centre.y()), float(centre.z())), viewport->size());
        QTest::mouseClick(viewport, Qt::LeftButton, {}, spot.toPoint());
        QCOMPARE(window.sceneTree()->selectedItem(), SceneItem::elementItem("bodies", 0));
        QCOMPARE(viewport->selection(), SceneItem::elementItem("bodies", 0));
    }

    void overlapsAreShownBeforeABakeAndCancelStartsNone() {
        QTemporaryDir folder;
        const QString scenePath = folder.filePath(QStringLiteral("rock.json"));
        writeSceneFile(sceneWithOverlappingBodies(), scenePath.toStdString());
        MainWindow window;
        QVERIFY(window.openScene(scenePath));
        QSignalSpy states(window.controller(), &SimulationController::stateChanged);

        QString shown;
        answerNextMessageBox([](QMessageBox& box) { return box.button(QMessageBox::Cancel); },
                             &shown);
        window.actions().bake->trigger();
        QVERIFY2(
            shown.contains(QStringLiteral("bodies[1] (\"Boulder\") overlaps bodies[0] (\"Rock\")")),
            qPrintable(shown));
        // A body in the water is how a scene floats one: the question leaves it out.
        QVERIFY2(!shown.contains(QStringLiteral("fluid_blocks")), qPrintable(shown));
        QVERIFY(states.isEmpty());
        QVERIFY(!window.controller()->isBusy());
        QVERIFY(!QFileInfo::exists(window.cacheDirectory()));
        const QString log = window.log()->toPlainText();
        QVERIFY2(log.contains(QStringLiteral("overlaps bodies[0]")), qPrintable(log));

        // Bake anyway starts it.
        answerNextMessageBox(
            [](QMessageBox& box) {
                return box.findChild<QAbstractButton*>(QStringLiteral("bakeAnywayButton"));
            },
            &shown);
        window.actions().bake->trigger();
        QVERIFY(window.controller()->isBusy());
        window.controller()->stop();
        QVERIFY(window.controller()->waitForIdle(30000));
    }

    void aSceneWithoutOverlapsBakesWithoutAsking() {
        QTemporaryDir folder;
        const QString scenePath = folder.filePath(QStringLiteral("tiny.json"));
        writeSceneFile(test::tinyDamBreak(), scenePath.toStdString());
        MainWindow window;
        QVERIFY(window.openScene(scenePath));
        window.actions().bake->trigger(); // interactive: a dialog here would block the test
        QVERIFY(window.controller()->isBusy());
        window.controller()->stop();
        QVERIFY(window.controller()->waitForIdle(30000));
    }

    //! The samples with bodies place them in the water or above it by design: none asks.
    void samplesWithBodiesBakeWithoutAsking_data() {
        QTest::addColumn<QString>("sample");
        QTest::newRow("buoyancy") << QStringLiteral("buoyancy.json");
        QTest::newRow("diving bunny") << QStringLiteral("diving_bunny.json");
    }

    void samplesWithBodiesBakeWithoutAsking() {
        QFETCH(QString, sample);
        QTemporaryDir cache;
        QString shown; // outlives the window and its watcher
        MainWindow window;
        QVERIFY(window.openScene(QStringLiteral(AIRTRAP_SOURCE_DIR "/samples/") + sample));
        window.useCacheFolder(cache.path());
        // Were a question to open, it is closed and the test fails below, not hangs.
        QTimer watcher(&window);
        connect(&watcher, &QTimer::timeout, &window, [&shown] {
            for (QWidget* widget : QApplication::topLevelWidgets())
                if (auto* box = qobject_cast<QMessageBox*>(widget); box && box->isVisible()) {
                    shown = box->text() + QLatin1Char('\n') + box->informativeText();
                    box->reject();
                }
        });
        watcher.start(20);
        window.actions().bake->trigger();
        watcher.stop();
        QVERIFY2(shown.isEmpty(), qPrintable(shown));
        QVERIFY(window.controller()->isBusy());
        window.controller()->stop();
        QVERIFY(window.controller()->waitForIdle(60000));
        QVERIFY2(window.log()->toPlainText().contains(QStringLiteral("note: ")) ==
                     (sample == QStringLiteral("buoyancy.json")),
                 qPrintable(window.log()->toPlainText()));
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestBodies)
#include "TestBodies.moc"
