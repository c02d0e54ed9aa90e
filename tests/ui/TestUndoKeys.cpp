// Undo and Redo from the keyboard right after a value was typed into a parameter field and
// committed with Enter: the field keeps the focus but gives Ctrl+Z and Ctrl+Shift+Z to the
// editor's history, whose lines name the object, the parameter and the new value.
#include "document/SceneDocument.h"
#include "panels/NumberField.h"
#include "panels/ParameterEditor.h"
#include "panels/ParameterPanel.h"
#include "support/WidgetTestMain.h"
#include "window/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QLineEdit>
#include <QTest>
#include <QUndoStack>

namespace airtrap {

class TestUndoKeys : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> window_;

    SceneDocument& document() const { return window_->document(); }

    template <class Field>
    Field* fieldOf(const char* key, const char* name) const {
        auto* editor = window_->findChild<ParameterEditor*>(QString::fromLatin1(key));
        return editor ? editor->findChild<Field*>(QString::fromLatin1(name)) : nullptr;
    }

    //! Select all, type, Enter, as a user does; the field keeps the focus.
    static void typeAndEnter(QWidget* field, const QString& text) {
        field->setFocus();
        QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(field, text);
        QTest::keyClick(field, Qt::Key_Return);
    }

private Q_SLOTS:
    void init() {
        window_ = std::make_unique<MainWindow>();
        window_->setInteractive(false);
        QVERIFY(window_->openScene(QStringLiteral(AIRTRAP_SOURCE_DIR "/samples/dam_break.json")));
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        // Window shortcuts fire only in the active window; without a window manager (Xvfb) the
        // window takes the input focus itself.
        window_->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(window_.get()));
    }

    void cleanup() { window_.reset(); }

    void ctrlZUndoesATypedValueWhileTheFieldHasTheFocus() {
        window_->findChild<ParameterPanel*>()->showItem(SceneItem::sectionItem("solver"));
        auto* spacing = fieldOf<NumberField>("particle_spacing", "field");
        QVERIFY(spacing != nullptr);
        typeAndEnter(spacing, QStringLiteral("0.035"));
        QCOMPARE(document().scene().solver.particleSpacing, 0.035);
        QCOMPARE(QApplication::focusWidget(), spacing);
        QCOMPARE(document().undoStack()->text(0),
                 QStringLiteral("Set Solver particle spacing to 0.035 m"));

        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(document().scene().solver.particleSpacing, 0.02);
        QCOMPARE(spacing->text(), QStringLiteral("0.02"));
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Z,
                        Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(document().scene().solver.particleSpacing, 0.035);
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(document().scene().solver.particleSpacing, 0.035);
    }

    void whileTypingCtrlZUndoesTheTypingOnly() {
        window_->findChild<ParameterPanel*>()->showItem(SceneItem::sectionItem("solver"));
        auto* spacing = fieldOf<NumberField>("particle_spacing", "field");
        typeAndEnter(spacing, QStringLiteral("0.03"));
        QTest::keyClicks(spacing, QStringLiteral("5"));
        QTest::keyClick(spacing, Qt::Key_Z, Qt::ControlModifier);
        // The document keeps its value; the field undid the digit typed after it.
        QCOMPARE(document().scene().solver.particleSpacing, 0.03);
        QCOMPARE(document().undoStack()->index(), 1);
        QCOMPARE(spacing->text(), QStringLiteral("0.03"));
    }

    void aNameFieldGivesUpTheKeysToo() {
        const SceneItem block = SceneItem::elementItem("fluid_blocks", 0);
        window_->findChild<ParameterPanel*>()->showItem(block);
        auto* name = fieldOf<QLineEdit>("name", "text");
        QVERIFY(name != nullptr);
        const QString before = name->text();
        typeAndEnter(name, QStringLiteral("Reservoir"));
        QCOMPARE(document().elementName(block), QStringLiteral("Reservoir"));
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(document().elementName(block), before);
    }

    void historyLinesNameObjectParameterValueAndUnit() {
        const SceneItem body = document().addElement("bodies");
        document().renameElement(body, QStringLiteral("Cube"));
        QVERIFY(document().editParameter(body, "density", 2000.0).isEmpty());
        const QUndoStack* stack = document().undoStack();
        QCOMPARE(stack->text(stack->count() - 1), QStringLiteral("Set Cube density to 2000 kg/m³"));
        QVERIFY(
            document().editParameter(SceneItem::sectionItem("solver"), "max_speed", 3.0).isEmpty());
        QCOMPARE(stack->text(stack->count() - 1),
                 QStringLiteral("Set Solver maximum speed to 3 m/s"));
    }

    void aSliderDragNamesItsLastValue() {
        const SceneItem solver = SceneItem::sectionItem("solver");
        const int drag = document().newDragSession();
        document().editParameter(solver, "particle_spacing", 0.03, drag);
        document().editParameter(solver, "particle_spacing", 0.04, drag);
        const QUndoStack* stack = document().undoStack();
        QCOMPARE(stack->count(), 1);
        QCOMPARE(stack->text(0), QStringLiteral("Set Solver particle spacing to 0.04 m"));
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestUndoKeys)
#include "TestUndoKeys.moc"
