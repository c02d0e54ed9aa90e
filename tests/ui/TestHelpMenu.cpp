// Help: the editor guide (docs/EDITOR.md, built in with its picture, on F1) and a sheet of every
// keyboard shortcut (Ctrl+F1), read from the window's own actions.
#include "support/WidgetTestMain.h"
#include "window/GuideDialog.h"
#include "window/MainWindow.h"
#include "window/ShortcutSheet.h"

#include <QAction>
#include <QImage>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>
#include <QTest>
#include <QTextBrowser>

namespace airtrap {

class TestHelpMenu : public QObject {
    Q_OBJECT

    static QStringList menuTexts(const QMenu* menu) {
        QStringList texts;
        for (const QAction* action : menu->actions())
            if (!action->isSeparator())
                texts << action->text();
        return texts;
    }

private Q_SLOTS:
    void theHelpMenuOffersTheGuideAndTheShortcuts() {
        MainWindow window;
        const QMenu* help = window.findChild<QMenu*>(QStringLiteral("helpMenu"));
        QVERIFY(help != nullptr);
        QCOMPARE(menuTexts(help), (QStringList{QStringLiteral("Editor &Guide"),
                                               QStringLiteral("&Keyboard Shortcuts"),
                                               QStringLiteral("&About Airtrap")}));
    }

    void theShortcutSheetListsEveryKeyOfTheWindow() {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QAction* sheetAction = window.findChild<QAction*>(QStringLiteral("shortcutSheetAction"));
        QCOMPARE(sheetAction->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_F1));
        sheetAction->trigger();
        const ShortcutSheet* sheet = window.findChild<ShortcutSheet*>();
        QVERIFY2(sheet != nullptr, "Keyboard Shortcuts opened no sheet");
        QVERIFY(sheet->isVisible());
        QMap<QString, QString> keysOf;
        for (int row = 0; row < sheet->table()->rowCount(); ++row)
            keysOf[sheet->table()->item(row, 1)->text()] = sheet->table()->item(row, 0)->text();
        QCOMPARE(keysOf.value(QStringLiteral("Bake")), QStringLiteral("Ctrl+B"));
        QCOMPARE(keysOf.value(QStringLiteral("Open Scene")), QStringLiteral("Ctrl+O"));
        QCOMPARE(keysOf.value(QStringLiteral("Undo")), QStringLiteral("Ctrl+Z"));
        QCOMPARE(keysOf.value(QStringLiteral("Keyboard Shortcuts")), QStringLiteral("Ctrl+F1"));
        QCOMPARE(keysOf.value(QStringLiteral("Orbit the view")), QStringLiteral("Left drag"));
        // Every action with keys is there.
        int withKeys = 0;
        for (const QAction* action : window.findChildren<QAction*>())
            withKeys += action->shortcuts().isEmpty() ? 0 : 1;
        QCOMPARE(sheet->table()->rowCount(), withKeys + 5);
    }

    void theGuideIsBuiltInWithItsPicture() {
        MainWindow window;
        QAction* action = window.findChild<QAction*>(QStringLiteral("guideAction"));
        QCOMPARE(action->shortcut(), QKeySequence(QKeySequence::HelpContents));
        QCOMPARE(action->shortcut(), QKeySequence(Qt::Key_F1));
        action->trigger();
        const GuideDialog* guide = window.findChild<GuideDialog*>();
        QVERIFY2(guide != nullptr, "Editor Guide opened no guide");
        const QString text = guide->browser()->toPlainText();
        QVERIFY2(text.startsWith(QStringLiteral("The editor")), qPrintable(text.left(80)));
        QVERIFY(text.contains(QStringLiteral("Open Recent")));
        QVERIFY(!QImage(QStringLiteral(":/docs/images/editor.png")).isNull());
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestHelpMenu)
#include "TestHelpMenu.moc"
