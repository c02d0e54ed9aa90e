#include "window/RecentFiles.h"

#include "window/EditorSettings.h"

#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <algorithm>

namespace airtrap {

namespace {
constexpr auto kRecentFilesKey = "recentFiles";
} // namespace

RecentFiles::RecentFiles(QMenu* menu, QObject* parent) : QObject(parent), menu_(menu) {
    files_ = EditorSettings::store().value(kRecentFilesKey).toStringList();
    dropMissing();
    rebuildMenu();
    // A scene deleted or moved while the editor runs leaves the menu when it next opens.
    connect(menu_, &QMenu::aboutToShow, this, [this] {
        if (dropMissing())
            rebuildMenu();
    });
}

bool RecentFiles::dropMissing() {
    const qsizetype removed =
        files_.removeIf([](const QString& path) { return !QFileInfo::exists(path); });
    if (removed > 0)
        save();
    return removed > 0;
}

QString RecentFiles::label(const QString& path) const {
    const QFileInfo file(path);
    const auto sameName = [&](const QString& other) {
        return other != path && QFileInfo(other).fileName() == file.fileName();
    };
    if (std::none_of(files_.begin(), files_.end(), sameName))
        return file.fileName();
    // Two scenes of one name: the folder tells them apart, by its name when that is enough.
    const QString folder = file.dir().dirName();
    const bool folderNameShared =
        std::any_of(files_.begin(), files_.end(), [&](const QString& other) {
            return sameName(other) && QFileInfo(other).dir().dirName() == folder;
        });
    return file.fileName() + QStringLiteral(" — ") +
           (folderNameShared ? QDir::toNativeSeparators(file.absolutePath()) : folder);
}

void RecentFiles::add(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files_.removeAll(absolute);
    files_.prepend(absolute);
    while (files_.size() > kMaximumEntries)
        files_.removeLast();
    save();
    rebuildMenu();
}

void RecentFiles::remove(const QString& path) {
    files_.removeAll(QFileInfo(path).absoluteFilePath());
    save();
    rebuildMenu();
}

void RecentFiles::save() const {
    EditorSettings::store().setValue(kRecentFilesKey, files_);
}

void RecentFiles::rebuildMenu() {
    menu_->clear();
    for (int i = 0; i < files_.size(); ++i) {
        const QString& path = files_[i];
        // &1 … &9 give keyboard access to the first nine, as desktop editors do.
        // Menus take '&' as the next letter's shortcut: a file's own '&' is doubled.
        QString name = label(path);
        name.replace(QLatin1Char('&'), QStringLiteral("&&"));
        QAction* action =
            menu_->addAction(i < 9 ? QStringLiteral("&%1  %2").arg(i + 1).arg(name) : name);
        action->setToolTip(QDir::toNativeSeparators(path));
        action->setStatusTip(QDir::toNativeSeparators(path));
        connect(action, &QAction::triggered, this, [this, path] { Q_EMIT fileChosen(path); });
    }
    menu_->setEnabled(!files_.isEmpty());
}

} // namespace airtrap
