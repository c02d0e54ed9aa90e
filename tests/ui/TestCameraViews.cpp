// The viewport's camera from the View menu and its keys: front, side, top and the three-quarter
// perspective view, the orthographic switch, and framing the selected object.
#include "panels/SceneTreePanel.h"
#include "support/WidgetTestMain.h"
#include "viewport/OrbitCamera.h"
#include "viewport/ViewportWidget.h"
#include "window/EditorActions.h"
#include "window/MainWindow.h"

#include <QAction>
#include <QMenu>
#include <QTest>

namespace airtrap {

class TestCameraViews : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> window_;

    const OrbitCamera& camera() const { return window_->viewport()->camera(); }
    const EditorActions& actions() const { return window_->actions(); }

private Q_SLOTS:
    void init() {
        window_ = std::make_unique<MainWindow>();
        window_->setInteractive(false);
        QVERIFY(window_->openScene(QStringLiteral(AIRTRAP_SOURCE_DIR "/samples/pouring.json")));
        window_->resize(1200, 800);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }

    void cleanup() { window_.reset(); }

    void presetsAreInTheViewMenuOnTheNumberKeys() {
        const auto* menu = window_->findChild<QMenu*>(QStringLiteral("cameraMenu"));
        QVERIFY(menu != nullptr);
        QVERIFY(menu->actions().contains(actions().viewFront));
        QVERIFY(menu->actions().contains(actions().orthographic));
        QCOMPARE(actions().viewFront->shortcut(), QKeySequence(Qt::Key_1));
        QCOMPARE(actions().viewSide->shortcut(), QKeySequence(Qt::Key_3));
        QCOMPARE(actions().viewTop->shortcut(), QKeySequence(Qt::Key_7));
        QCOMPARE(actions().viewPerspective->shortcut(), QKeySequence(Qt::Key_0));
        QCOMPARE(actions().orthographic->shortcut(), QKeySequence(Qt::Key_5));
        QCOMPARE(actions().frameSelected->shortcut(), QKeySequence(Qt::SHIFT | Qt::Key_F));
    }

    void eachPresetLooksFromItsSide() {
        actions().viewFront->trigger();
        QCOMPARE(camera().yaw(), 0.0f);
        QCOMPARE(camera().pitch(), 0.0f);
        actions().viewSide->trigger();
        QCOMPARE(camera().yaw(), 90.0f);
        actions().viewTop->trigger();
        QCOMPARE(camera().pitch(), 89.0f);
        actions().viewPerspective->trigger();
        QCOMPARE(camera().yaw(), OrbitCamera().yaw());
        QCOMPARE(camera().pitch(), OrbitCamera().pitch());
    }

    void orthographicSwitchesAndThePerspectivePresetLeavesIt() {
        actions().orthographic->trigger();
        QVERIFY(window_->viewport()->isOrthographic());
        actions().viewFront->trigger(); // a preset keeps the projection
        QVERIFY(window_->viewport()->isOrthographic());
        actions().viewPerspective->trigger();
        QVERIFY(!window_->viewport()->isOrthographic());
        QVERIFY(!actions().orthographic->isChecked());
    }

    void frameSelectedFitsTheSelectedObject() {
        const SceneItem pool = SceneItem::elementItem("fluid_blocks", 0);
        window_->sceneTree()->selectItem(pool);
        QCOMPARE(window_->viewport()->selection(), pool);
        actions().frameAll->trigger();
        const float allDistance = camera().distance();
        actions().frameSelected->trigger();
        // The pool is 1 m × 0.1 m × 0.5 m with its minimum corner at the origin.
        QVERIFY(qFuzzyCompare(camera().target(), QVector3D(0.5f, 0.05f, 0.25f)));
        QVERIFY2(camera().distance() < allDistance,
                 qPrintable(QStringLiteral("%1 vs %2").arg(camera().distance()).arg(allDistance)));
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestCameraViews)
#include "TestCameraViews.moc"
