// Where the editor's bakes go. A scene whose folder cannot be written (an installed samples
// folder) asks where to put its frames and proposes a folder of its own in the user's cache; the
// log says where frames go; Clear Cache removes a cache folder the editor made, and keeps one the
// user made or one that holds other files.
#include "BakeTestScenes.h"
#include "controller/SimulationController.h"
#include "scene/SceneJson.h"
#include "support/WidgetTestMain.h"
#include "window/CacheLocation.h"
#include "window/EditorActions.h"
#include "window/LogPanel.h"
#include "window/MainWindow.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <memory>

namespace airtrap {

class TestCacheFolders : public QObject {
    Q_OBJECT

    //! A folder of each test's own: the editor remembers the cache folders it made by path.
    std::unique_ptr<QTemporaryDir> folder_;
    QString scenePath_;

    //! Answers the next question the window asks with the button named `button` ("" for
    //! Cancel), and returns what it asked ("" when nothing was asked).
    static QString answer(MainWindow& window, const QString& button, QAction* trigger) {
        QString asked;
        QTimer watcher;
        connect(&watcher, &QTimer::timeout, &window, [&asked, &button] {
            for (QWidget* widget : QApplication::topLevelWidgets()) {
                auto* box = qobject_cast<QMessageBox*>(widget);
                if (box == nullptr || !box->isVisible())
                    continue;
                asked = box->text() + QLatin1Char('\n') + box->informativeText();
                if (auto* chosen = box->findChild<QAbstractButton*>(button); !button.isEmpty())
                    chosen->click();
                else
                    box->reject();
            }
        });
        watcher.start(20);
        trigger->trigger();
        watcher.stop();
        return asked;
    }

    //! Opens the scene in `window` without dialogs and bakes it; returns the cache folder.
    QString bakeQuietly(MainWindow& window) const {
        window.setInteractive(false);
        if (!window.openScene(scenePath_))
            return {};
        window.actions().bake->trigger();
        return window.controller()->waitForIdle(60000) ? window.cacheDirectory() : QString();
    }

    //! The scene's folder is read-only, as an installed samples folder is; others are not.
    void makeSceneFolderReadOnly(MainWindow& window) const {
        const QString sceneFolder = folder_->path();
        window.cacheLocation().setWritableTest(
            [sceneFolder](const QString& folder) { return folder != sceneFolder; });
    }

private Q_SLOTS:
    void init() {
        folder_ = std::make_unique<QTemporaryDir>();
        scenePath_ = folder_->filePath(QStringLiteral("tiny.json"));
        writeSceneFile(test::tinyDamBreak(), scenePath_.toStdString());
    }

    void cleanup() {
        QDir(CacheLocation::perUser(scenePath_)).removeRecursively();
        QDir(CacheLocation::besideScene(scenePath_)).removeRecursively();
    }

    void aReadOnlySceneFolderAsksAndBakesIntoTheUsersCache() {
        MainWindow window;
        makeSceneFolderReadOnly(window);
        QVERIFY(window.openScene(scenePath_));
        const QString proposed = CacheLocation::perUser(scenePath_);
        QVERIFY2(
            proposed.startsWith(QStandardPaths::writableLocation(QStandardPaths::CacheLocation)),
            qPrintable(proposed));
        QCOMPARE(window.cacheDirectory(), proposed);

        const QString asked =
            answer(window, QStringLiteral("bakeInUserCacheButton"), window.actions().bake);
        QVERIFY2(asked.contains(QStringLiteral("“tiny.json” is in a folder you cannot write to")),
                 qPrintable(asked));
        QVERIFY2(asked.contains(QDir::toNativeSeparators(proposed)), qPrintable(asked));
        QVERIFY(window.controller()->waitForIdle(60000));
        QVERIFY(QFileInfo::exists(proposed + QStringLiteral("/frame_0004.atf")));
        QVERIFY(!QFileInfo::exists(CacheLocation::besideScene(scenePath_)));
        const QString log = window.log()->toPlainText();
        QVERIFY2(log.contains(QStringLiteral("its frames go to ") + proposed), qPrintable(log));
        QVERIFY2(log.contains(QStringLiteral("Baking tiny.json into ") + proposed),
                 qPrintable(log));

        // Reopened later, the scene finds its frames there and asks nothing more.
        MainWindow later;
        makeSceneFolderReadOnly(later);
        QVERIFY(later.openScene(scenePath_));
        QCOMPARE(later.cacheDirectory(), proposed);
    }

    void cancellingTheQuestionStartsNothing() {
        MainWindow window;
        makeSceneFolderReadOnly(window);
        QVERIFY(window.openScene(scenePath_));
        const QString asked = answer(window, QString(), window.actions().bake);
        QVERIFY(!asked.isEmpty());
        QVERIFY(!window.controller()->isBusy());
        QVERIFY(!QFileInfo::exists(CacheLocation::perUser(scenePath_)));
        QVERIFY(window.log()->toPlainText().contains(QStringLiteral("Bake cancelled")));
    }

    void aWritableSceneFolderIsNotAskedAbout() {
        MainWindow window;
        QVERIFY(window.openScene(scenePath_));
        const QString asked = answer(window, QString(), window.actions().bake);
        QVERIFY2(asked.isEmpty(), qPrintable(asked));
        QVERIFY(window.controller()->waitForIdle(60000));
        QVERIFY(QFileInfo::exists(CacheLocation::besideScene(scenePath_)));
    }

    void clearCacheRemovesTheFolderTheEditorMade() {
        MainWindow window;
        const QString cache = bakeQuietly(window);
        QVERIFY(!cache.isEmpty());
        QVERIFY(QDir(cache + QStringLiteral("/post")).mkpath(QStringLiteral(".")));
        QTRY_VERIFY(window.actions().clearCache->isEnabled());
        window.actions().clearCache->trigger();
        QVERIFY2(!QFileInfo::exists(cache), qPrintable(QDir(cache).entryList().join(u' ')));
        QVERIFY(window.log()->toPlainText().contains(
            QStringLiteral("Cleared the cache and removed its folder ") + cache));
    }

    void clearCacheKeepsAFolderWithOtherFiles() {
        MainWindow window;
        const QString cache = bakeQuietly(window);
        QVERIFY(!cache.isEmpty());
        // An export made into the cache folder (the Export dialog's default) is the user's.
        QVERIFY(QDir(cache).mkpath(QStringLiteral("export")));
        QFile exported(cache + QStringLiteral("/export/water_0001.obj"));
        QVERIFY(exported.open(QIODevice::WriteOnly));
        exported.close();
        QTRY_VERIFY(window.actions().clearCache->isEnabled());
        window.actions().clearCache->trigger();
        QVERIFY(QFileInfo::exists(exported.fileName()));
        QCOMPARE(QDir(cache).entryList(QDir::Files), QStringList());
        QVERIFY(window.log()->toPlainText().contains(QStringLiteral("kept its folder ") + cache));
    }

    void clearCacheLeavesAFolderTheUserMade() {
        const QString cache = CacheLocation::besideScene(scenePath_);
        QVERIFY(QDir().mkpath(cache));
        MainWindow window;
        QCOMPARE(bakeQuietly(window), cache);
        QTRY_VERIFY(window.actions().clearCache->isEnabled());
        window.actions().clearCache->trigger();
        QVERIFY(QFileInfo::exists(cache));
        QVERIFY(!QFileInfo::exists(cache + QStringLiteral("/frame_0001.atf")));
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestCacheFolders)
#include "TestCacheFolders.moc"
