// The editor's main window comes up with its menus and a working OpenGL 3.3 core viewport.
// Runs under a real (virtual) X server: QOpenGLWidget crashes on the offscreen platform.
#include "document/SceneDocument.h"
#include "support/WidgetTestMain.h"
#include "viewport/ViewportWidget.h"
#include "window/EditorActions.h"
#include "window/EditorSettings.h"
#include "window/MainWindow.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QOpenGLContext>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

namespace airtrap {

class TestMainWindow : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        // The test main's scratch store keeps the geometry the test saves away from the user's
        // settings; start it empty, so remembersGeometry() cannot pass on a previous run's.
        EditorSettings::store().clear();
    }

    void showsWithFileMenu() {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.windowTitle().endsWith(QStringLiteral("Airtrap")));

        QMenu* file = window.fileMenu();
        QVERIFY(file);
        QVERIFY(window.menuBar()->actions().contains(file->menuAction()));
        QCOMPARE(file->title(), QStringLiteral("&File"));

        const QList<QAction*> actions = file->actions();
        QVERIFY(actions.contains(window.openSceneAction()));
        QVERIFY(window.openSceneAction()->text().startsWith(QStringLiteral("&Open Scene")));
        QVERIFY(actions.contains(window.quitAction()));
        QCOMPARE(window.quitAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_Q));
    }

    void viewportHasCoreContextAndClears() {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));

        ViewportWidget* viewport = window.viewport();
        QVERIFY(viewport);
        QVERIFY(viewport->isVisible());
        // The context is created on the first paint, which may follow the expose event.
        QTRY_VERIFY_WITH_TIMEOUT(viewport->isValid(), 5000);
        QOpenGLContext* context = viewport->context();
        QVERIFY(context);
        QVERIFY(context->isValid());
        const QSurfaceFormat format = context->format();
        QCOMPARE(format.profile(), QSurfaceFormat::CoreProfile);
        QVERIFY2(format.version() >= qMakePair(3, 3), qPrintable(QStringLiteral("OpenGL %1.%2")
                                                                     .arg(format.majorVersion())
                                                                     .arg(format.minorVersion())));

        const QImage image = viewport->grabFramebuffer();
        QVERIFY(!image.isNull());
        const QSize expected = viewport->size() * viewport->devicePixelRatio();
        QCOMPARE(image.size(), expected);
        const QColor centre = image.pixelColor(image.width() / 2, image.height() / 2);
        QCOMPARE(centre.name(QColor::HexArgb), ViewportWidget::clearColor().name(QColor::HexArgb));
    }

    void remembersGeometry() {
        const QSize size(900, 700);
        {
            MainWindow window;
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            window.resize(size);
            QTRY_COMPARE(window.size(), size);
            QVERIFY(window.close());
        }
        MainWindow window;
        QCOMPARE(window.size(), size);
    }

    void viewMenuTogglesTheWaterAndBubblesThroughItAndRemembersThem() {
        {
            MainWindow window;
            const EditorActions& actions = window.actions();
            QAction* water = actions.showWater;
            QAction* through = actions.bubblesThroughWater;
            for (QAction* action : {water, through}) {
                QVERIFY(window.viewMenu()->actions().contains(action));
                QVERIFY(action->isCheckable());
                QVERIFY(action->isChecked());
            }
            QCOMPARE(water->shortcut(), QKeySequence(Qt::Key_W));
            ViewportWidget* viewport = window.viewport();
            QVERIFY(viewport->showsWater());
            QVERIFY(viewport->drawsBubblesThroughWater());

            water->trigger();
            QVERIFY(!viewport->showsWater());
            QVERIFY(viewport->drawsBubblesThroughWater());
            through->trigger();
            QVERIFY(!viewport->drawsBubblesThroughWater());
        }
        // A new window starts as the last one was left, without waiting for a quit.
        MainWindow window;
        QVERIFY(!window.actions().showWater->isChecked());
        QVERIFY(!window.actions().bubblesThroughWater->isChecked());
        QVERIFY(!window.viewport()->showsWater());
        QVERIFY(!window.viewport()->drawsBubblesThroughWater());
        window.actions().showWater->trigger();
        window.actions().bubblesThroughWater->trigger();
        QVERIFY(window.viewport()->showsWater());
        QVERIFY(window.viewport()->drawsBubblesThroughWater());
    }

    void openSceneNamesItInTitleAndStatusBar() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("tank.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format_version": 1, "name": "Small tank"})");
        file.close();

        MainWindow window;
        window.setInteractive(false);
        QVERIFY(window.openScene(path));
        QVERIFY(window.statusBar()->currentMessage().contains(QStringLiteral("tank.json")));
        QVERIFY(window.windowTitle().contains(QStringLiteral("tank.json")));
        QCOMPARE(window.document().scene().name, std::string("Small tank"));

        QVERIFY(!window.openScene(dir.filePath(QStringLiteral("missing.json"))));
        QVERIFY(window.statusBar()->currentMessage().contains(QStringLiteral("missing.json")));
        QCOMPARE(window.document().scene().name, std::string("Small tank"));
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestMainWindow)
#include "TestMainWindow.moc"
