#include "window/RecentFiles.h"

#include "window/EditorSettings.h"

#include <QDir>
#include <QFileInfo>
#include <QMenu>

namespace airtrap {

namespace {
constexpr auto kRecentFilesKey = "recentFiles";
} // namespace

RecentFiles::RecentFiles(QMenu* menu, QObject* parent) : QObject(parent), menu_(menu) {
    files_ = EditorSettings::store().value(kRecentFilesKey).toStringList();
    rebuildMenu();
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
        const QString label =
            i < 9 ? QStringLiteral("&%1  %2").arg(i + 1).arg(QFileInfo(path).fileName())
                  : QFileInfo(path).fileName();
        QAction* action = menu_->addAction(label);
        action->setToolTip(QDir::toNativeSeparators(path));
        action->setStatusTip(QDir::toNativeSeparators(path));
        connect(action, &QAction::triggered, this, [this, path] { Q_EMIT fileChosen(path); });
    }
    menu_->setEnabled(!files_.isEmpty());
}

} // namespace airtrap
