// File ▸ Open Recent: the newest scene first, at most ten; two scenes of one name are told apart
// by their folders (by the folder's name, or its whole path when the names agree too); a scene
// that no longer exists leaves the menu; and the list lives in the test's scratch settings, never
// in the user's.
#include "support/WidgetTestMain.h"
#include "window/EditorSettings.h"
#include "window/RecentFiles.h"

#include <QDir>
#include <QFile>
#include <QMenu>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

namespace airtrap {

class TestRecentFiles : public QObject {
    Q_OBJECT

    QTemporaryDir root_;

    //! Creates `relative` (with its folders) under the test's folder; its absolute path.
    QString touch(const QString& relative) {
        const QString path = root_.filePath(relative);
        QDir().mkpath(QFileInfo(path).absolutePath());
        QFile file(path);
        [[maybe_unused]] const bool opened = file.open(QIODevice::WriteOnly);
        return QFileInfo(path).absoluteFilePath();
    }

    static QStringList texts(const QMenu& menu) {
        QStringList list;
        for (const QAction* action : menu.actions())
            list << action->text();
        return list;
    }

private Q_SLOTS:
    void init() { EditorSettings::store().clear(); }

    void theListIsKeptInTheScratchStoreNotTheUsers() {
        const QSettings user(QStringLiteral("Airtrap"), QStringLiteral("Airtrap"));
        QVERIFY2(EditorSettings::store().fileName() != user.fileName(),
                 qPrintable(user.fileName()));
        const QVariant usersList = user.value(QStringLiteral("recentFiles"));
        QMenu menu;
        RecentFiles recent(&menu);
        recent.add(touch(QStringLiteral("tank.json")));
        QCOMPARE(EditorSettings::store().value(QStringLiteral("recentFiles")).toStringList(),
                 QStringList{touch(QStringLiteral("tank.json"))});
        QCOMPARE(QSettings(QStringLiteral("Airtrap"), QStringLiteral("Airtrap"))
                     .value(QStringLiteral("recentFiles")),
                 usersList);
    }

    void scenesOfOneNameShowTheirFolders() {
        QMenu menu;
        RecentFiles recent(&menu);
        const QString pouring = touch(QStringLiteral("pouring/scene.json"));
        const QString bunny = touch(QStringLiteral("bunny/scene.json"));
        const QString twin = touch(QStringLiteral("other/bunny/scene.json"));
        const QString alone = touch(QStringLiteral("tank & jet.json"));
        recent.add(pouring);
        QCOMPARE(recent.label(pouring), QStringLiteral("scene.json"));
        recent.add(bunny);
        QCOMPARE(recent.label(pouring), QStringLiteral("scene.json — pouring"));
        recent.add(twin);
        QCOMPARE(recent.label(bunny), QStringLiteral("scene.json — ") +
                                          QDir::toNativeSeparators(root_.filePath("bunny")));
        recent.add(alone);
        QCOMPARE(texts(menu).first(), QStringLiteral("&1  tank && jet.json"));
        QCOMPARE(texts(menu).at(3), QStringLiteral("&4  scene.json — pouring"));
    }

    void aSceneThatIsGoneLeavesTheMenu() {
        const QString kept = touch(QStringLiteral("kept.json"));
        const QString gone = touch(QStringLiteral("gone.json"));
        {
            QMenu menu;
            RecentFiles recent(&menu);
            recent.add(kept);
            recent.add(gone);
            QFile::remove(gone);
            // While the editor runs: when the menu next opens.
            Q_EMIT menu.aboutToShow();
            QCOMPARE(recent.files(), QStringList{kept});
            QCOMPARE(texts(menu), QStringList{QStringLiteral("&1  kept.json")});
        }
        const QString later = touch(QStringLiteral("later.json"));
        QMenu menu;
        RecentFiles recent(&menu);
        recent.add(later);
        QFile::remove(later);
        // Across sessions: when the editor starts.
        QMenu next;
        RecentFiles restarted(&next);
        QCOMPARE(restarted.files(), QStringList{kept});
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestRecentFiles)
#include "TestRecentFiles.moc"
