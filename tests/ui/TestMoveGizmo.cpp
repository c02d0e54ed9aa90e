// The move gizmo: arrows at the selected object's centre that slide it along a world axis. The
// offset follows the cursor along the axis, rounded to a millimetre; a body, an obstacle, an
// emitter or a fluid block (both corners) moves, and each drag is one undo step.
#include "document/ElementMover.h"
#include "document/SceneDocument.h"
#include "panels/SceneTreePanel.h"
#include "support/WidgetTestMain.h"
#include "viewport/MoveGizmo.h"
#include "viewport/ViewportWidget.h"
#include "window/EditorActions.h"
#include "window/MainWindow.h"

#include <QAction>
#include <QTest>
#include <QUndoStack>

namespace airtrap {

namespace {

const QSize kView(800, 600);

QVector3D tipOf(const MoveGizmo& gizmo, int axis) {
    QVector3D direction;
    direction[axis] = gizmo.armLength();
    return *gizmo.origin() + direction;
}

} // namespace

class TestMoveGizmo : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void anArrowIsTakenNearItAndFollowsTheCursorAlongItsAxis() {
        OrbitCamera camera; // the three-quarter view
        camera.fit(Aabb{Vec3d(0, 0, 0), Vec3d(1, 1, 1)}, 800.0f / 600.0f);
        MoveGizmo gizmo;
        gizmo.setOrigin(QVector3D(0.5f, 0.5f, 0.5f));
        gizmo.fitTo(camera, kView);
        QVERIFY(gizmo.armLength() > 0.0f);
        const QPointF xTip = camera.project(tipOf(gizmo, 0), kView);
        QCOMPARE(gizmo.axisAt(xTip, camera, kView), std::optional<int>(0));
        QCOMPARE(gizmo.axisAt(camera.project(tipOf(gizmo, 1), kView), camera, kView),
                 std::optional<int>(1));
        QCOMPARE(gizmo.axisAt(QPointF(5.0, 5.0), camera, kView), std::nullopt);

        QVERIFY(gizmo.beginDrag(0, xTip, camera, kView));
        // The cursor where the point 0.2 m further along x shows: the offset is 0.2 m.
        const QPointF further = camera.project(tipOf(gizmo, 0) + QVector3D(0.2f, 0, 0), kView);
        QCOMPARE(gizmo.dragOffset(further, camera, kView), 0.2);
        // Off the axis on screen, the nearest point along it counts.
        const QPointF aside = further + QPointF(0.0, 30.0);
        QVERIFY(std::abs(gizmo.dragOffset(aside, camera, kView) - 0.2) < 0.1);
        const double offset = gizmo.dragOffset(aside, camera, kView);
        QCOMPARE(std::round(offset * 1000.0) / 1000.0, offset); // whole millimetres
        gizmo.endDrag();
        QVERIFY(!gizmo.draggedAxis());
    }

    void anAxisPointingAtTheEyeCannotBeDragged() {
        OrbitCamera camera;
        camera.setAngles(0.0f, 0.0f); // looking along −z
        camera.fit(Aabb{Vec3d(0, 0, 0), Vec3d(1, 1, 1)}, 800.0f / 600.0f);
        MoveGizmo gizmo;
        gizmo.setOrigin(QVector3D(0.5f, 0.5f, 0.5f));
        gizmo.fitTo(camera, kView);
        QVERIFY(!gizmo.beginDrag(2, camera.project(*gizmo.origin(), kView), camera, kView));
    }

    void aFluidBlockMovesByBothCornersInOneUndoStep() {
        SceneDocument document;
        const SceneItem block = SceneItem::elementItem("fluid_blocks", 0);
        const FluidBlock before = document.scene().fluidBlocks.at(0);
        ElementMover mover(document);
        mover.begin(block);
        QVERIFY(mover.moveTo(1, 0.05).isEmpty());
        QVERIFY(mover.moveTo(1, 0.1).isEmpty());
        mover.end();
        const FluidBlock& after = document.scene().fluidBlocks.at(0);
        QVERIFY(after.min.isApprox(before.min + Vec3d(0, 0.1, 0)));
        QVERIFY(after.max.isApprox(before.max + Vec3d(0, 0.1, 0)));
        QCOMPARE(document.undoStack()->count(), 1);
        QCOMPARE(document.undoStack()->text(0), QStringLiteral("Move Water along y by 0.1 m"));
        document.undoStack()->undo();
        QVERIFY(document.scene().fluidBlocks.at(0).min.isApprox(before.min));
        QVERIFY(document.scene().fluidBlocks.at(0).max.isApprox(before.max));
        QVERIFY(!ElementMover::canMove(SceneItem::sectionItem("container")));
    }

    void draggingAnArrowInTheViewportMovesTheBodyAsOneStep() {
        MainWindow window;
        window.setInteractive(false);
        window.resize(1200, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        SceneDocument& document = window.document();
        const SceneItem body = document.addElement("bodies");
        window.sceneTree()->selectItem(body);
        window.actions().frameSelected->trigger();
        ViewportWidget* viewport = window.viewport();
        QTest::qWait(100); // a paint puts the arrows at the body
        const MoveGizmo& gizmo = viewport->moveGizmo();
        QVERIFY(gizmo.origin().has_value());
        const Vec3d start = document.scene().bodies.at(0).position;
        const int steps = document.undoStack()->count();

        const OrbitCamera& camera = viewport->camera();
        const QPoint grab = camera.project(tipOf(gizmo, 0), viewport->size()).toPoint();
        const QPoint drop =
            camera.project(tipOf(gizmo, 0) + QVector3D(0.05f, 0, 0), viewport->size()).toPoint();
        QTest::mousePress(viewport, Qt::LeftButton, {}, grab);
        for (int i = 1; i <= 5; ++i)
            QTest::mouseMove(viewport, grab + (drop - grab) * i / 5);
        QTest::mouseRelease(viewport, Qt::LeftButton, {}, drop);

        const Vec3d moved = document.scene().bodies.at(0).position;
        QVERIFY2(std::abs(moved.x() - start.x() - 0.05) < 0.005,
                 qPrintable(QString::number(moved.x() - start.x())));
        QCOMPARE(moved.y(), start.y());
        QCOMPARE(moved.z(), start.z());
        QCOMPARE(document.undoStack()->count(), steps + 1);
        QVERIFY(document.undoStack()->text(steps).startsWith(QStringLiteral("Move Body along x")));
        // The press on the arrow selected nothing else and orbited nothing.
        QCOMPARE(viewport->selection(), body);
        document.undoStack()->undo();
        QCOMPARE(document.scene().bodies.at(0).position, start);
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestMoveGizmo)
#include "TestMoveGizmo.moc"
