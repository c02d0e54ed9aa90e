#include "window/CacheFolderQuestion.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>

namespace airtrap {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("CacheFolderQuestion", text);
}

} // namespace

QString CacheFolderQuestion::ask(QWidget* parent, const QString& scenePath,
                                 const QString& proposed) {
    const QFileInfo scene(scenePath);
    QMessageBox box(QMessageBox::Question, tr("Where should the frames go?"),
                    tr("“%1” is in a folder you cannot write to:\n%2")
                        .arg(scene.fileName(), QDir::toNativeSeparators(scene.absolutePath())),
                    QMessageBox::Cancel, parent);
    box.setObjectName(QStringLiteral("cacheFolderQuestion"));
    box.setInformativeText(tr("Its frames can go to a folder of its own in your cache folder:\n%1")
                               .arg(QDir::toNativeSeparators(proposed)));
    QPushButton* useProposed = box.addButton(tr("Bake There"), QMessageBox::AcceptRole);
    useProposed->setObjectName(QStringLiteral("bakeInUserCacheButton"));
    QPushButton* choose = box.addButton(tr("Choose Folder…"), QMessageBox::ActionRole);
    choose->setObjectName(QStringLiteral("chooseCacheFolderButton"));
    box.setDefaultButton(useProposed);
    box.exec();
    if (box.clickedButton() == useProposed)
        return proposed;
    if (box.clickedButton() != choose)
        return {};
    const QString folder = QFileDialog::getExistingDirectory(parent, tr("Bake into"),
                                                             QFileInfo(proposed).absolutePath());
    if (folder.isEmpty())
        return {};
    return QDir(folder).filePath(scene.completeBaseName() + QStringLiteral(".cache"));
}

} // namespace airtrap
