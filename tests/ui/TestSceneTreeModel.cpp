// The scene tree over the document: sections and elements as rows; add, remove, duplicate and
// rename go through the undo stack and the rows follow every undo and redo.
#include "document/SceneDocument.h"
#include "model/SceneTreeModel.h"
#include "scene/SceneSchema.h"
#include "support/WidgetTestMain.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

namespace airtrap {

class TestSceneTreeModel : public QObject {
    Q_OBJECT

    static QString damBreak() {
        return QStringLiteral(AIRTRAP_SOURCE_DIR "/samples/dam_break.json");
    }

    static QModelIndex groupIndex(const SceneTreeModel& model, const char* section) {
        return model.indexOf(SceneItem::group(section));
    }

private Q_SLOTS:
    void rowsFollowTheSchema() {
        SceneDocument document;
        document.open(damBreak());
        SceneTreeModel model(document);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);

        QCOMPARE(model.rowCount(), static_cast<int>(SceneSchema::sections().size()));
        QCOMPARE(model.itemAt(model.index(0, 0)), SceneItem::sectionItem(""));
        QVERIFY(model.data(model.index(0, 0))
                    .toString()
                    .contains(QString::fromStdString(document.scene().name)));
        const QModelIndex blocks = groupIndex(model, "fluid_blocks");
        QVERIFY(blocks.isValid());
        QCOMPARE(model.rowCount(blocks), static_cast<int>(document.scene().fluidBlocks.size()));
        const QModelIndex first = model.index(0, 0, blocks);
        QCOMPARE(model.itemAt(first), SceneItem::elementItem("fluid_blocks", 0));
        QCOMPARE(model.data(first).toString(),
                 QString::fromStdString(document.scene().fluidBlocks[0].name));
        QCOMPARE(model.parent(first), blocks);
        QCOMPARE(model.indexOf(SceneItem::elementItem("fluid_blocks", 0)), first);
        QVERIFY(!model.indexOf(SceneItem::elementItem("fluid_blocks", 99)).isValid());
    }

    void bubblesIsASectionRow() {
        SceneDocument document;
        document.open(damBreak());
        SceneTreeModel model(document);
        const QModelIndex bubbles = model.indexOf(SceneItem::sectionItem("bubbles"));
        QVERIFY(bubbles.isValid());
        QVERIFY(!bubbles.parent().isValid());
        QCOMPARE(model.data(bubbles).toString(), QStringLiteral("Bubbles"));
        QCOMPARE(model.rowCount(bubbles), 0);
        QCOMPARE(model.itemAt(bubbles), SceneItem::sectionItem("bubbles"));
    }

    void addRemoveWithUndo() {
        SceneDocument document;
        document.open(damBreak());
        SceneTreeModel model(document);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        const QModelIndex obstacles = groupIndex(model, "obstacles");
        const int before = model.rowCount(obstacles);

        const SceneItem added = document.addElement("obstacles");
        QCOMPARE(model.rowCount(obstacles), before + 1);
        QCOMPARE(added, SceneItem::elementItem("obstacles", static_cast<std::size_t>(before)));
        QCOMPARE(document.scene().obstacles.back().name, std::string("Obstacle"));

        document.undoStack()->undo();
        QCOMPARE(model.rowCount(obstacles), before);
        QCOMPARE(static_cast<int>(document.scene().obstacles.size()), before);
        document.undoStack()->redo();
        QCOMPARE(model.rowCount(obstacles), before + 1);

        document.removeElement(added);
        QCOMPARE(model.rowCount(obstacles), before);
        document.undoStack()->undo();
        QCOMPARE(model.rowCount(obstacles), before + 1);
        QCOMPARE(model.data(model.indexOf(added)).toString(), QStringLiteral("Obstacle"));
    }

    void duplicateCopiesEveryParameter() {
        SceneDocument document;
        document.open(damBreak());
        SceneTreeModel model(document);
        const SceneItem original = SceneItem::elementItem("fluid_blocks", 0);
        QVERIFY(document.editParameter(original, "max", Vec3d(0.3, 0.6, 0.4)).isEmpty());
        const int commands = document.undoStack()->count();

        const SceneItem copy = document.duplicateElement(original);
        QCOMPARE(copy, SceneItem::elementItem("fluid_blocks", 1));
        const FluidBlock& a = document.scene().fluidBlocks[0];
        const FluidBlock& b = document.scene().fluidBlocks[1];
        QCOMPARE(b.name, a.name + " copy");
        QVERIFY(b.min == a.min);
        QVERIFY(b.max == Vec3d(0.3, 0.6, 0.4));
        QVERIFY(b.initialVelocity == a.initialVelocity);
        QCOMPARE(document.undoStack()->count(), commands + 1);
        QCOMPARE(model.rowCount(groupIndex(model, "fluid_blocks")), 2);

        document.undoStack()->undo();
        QCOMPARE(document.scene().fluidBlocks.size(), std::size_t(1));
    }

    void renameThroughTheModel() {
        SceneDocument document;
        document.open(damBreak());
        SceneTreeModel model(document);
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        QSignalSpy refused(&model, &SceneTreeModel::editRefused);
        const QModelIndex block = model.indexOf(SceneItem::elementItem("fluid_blocks", 0));
        QVERIFY(model.flags(block).testFlag(Qt::ItemIsEditable));
        QVERIFY(!model.flags(groupIndex(model, "fluid_blocks")).testFlag(Qt::ItemIsEditable));

        QVERIFY(model.setData(block, QStringLiteral("Column")));
        QCOMPARE(document.scene().fluidBlocks[0].name, std::string("Column"));
        QCOMPARE(changed.count(), 1);

        // An empty name is out of the declared 1–200 characters: refused, with the reason.
        QVERIFY(!model.setData(block, QStringLiteral("   ")));
        QCOMPARE(refused.count(), 1);
        QVERIFY(refused.first().first().toString().contains(QStringLiteral("name")));
        QCOMPARE(document.scene().fluidBlocks[0].name, std::string("Column"));

        document.undoStack()->undo();
        QCOMPARE(model.data(block).toString(),
                 QString::fromStdString(document.scene().fluidBlocks[0].name));
        QVERIFY(document.scene().fluidBlocks[0].name != "Column");
    }

    void openResetsTheTree() {
        SceneDocument document;
        SceneTreeModel model(document);
        QSignalSpy reset(&model, &QAbstractItemModel::modelReset);
        document.open(damBreak());
        QCOMPARE(reset.count(), 1);
        QVERIFY(!document.isModified());
        QCOMPARE(document.undoStack()->count(), 0);
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestSceneTreeModel)
#include "TestSceneTreeModel.moc"
