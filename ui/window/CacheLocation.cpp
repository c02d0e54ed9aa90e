#include "window/CacheLocation.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace airtrap {

namespace {

//! Enough of the path's hash to tell apart the scenes of one name a user has.
constexpr int kPathHashDigits = 8;

bool folderIsWritable(const QString& folder) {
    // access(W_OK): false on a read-only mount or a folder of another user, even for root on
    // the former.
    return QFileInfo(folder).isWritable();
}

} // namespace

CacheLocation::CacheLocation() : writable_(folderIsWritable) {}

QString CacheLocation::forScene(const QString& scenePath) const {
    return canBakeBeside(scenePath) ? besideScene(scenePath) : perUser(scenePath);
}

bool CacheLocation::canBakeBeside(const QString& scenePath) const {
    return !scenePath.isEmpty() && writable_(QFileInfo(scenePath).absolutePath());
}

QString CacheLocation::besideScene(const QString& scenePath) {
    const QFileInfo scene(scenePath);
    return scene.absoluteDir().filePath(scene.completeBaseName() + QStringLiteral(".cache"));
}

QString CacheLocation::perUser(const QString& scenePath) {
    const QDir userCache(QStandardPaths::writableLocation(QStandardPaths::CacheLocation));
    if (scenePath.isEmpty())
        return userCache.filePath(QStringLiteral("untitled.cache"));
    const QFileInfo scene(scenePath);
    const QByteArray hash =
        QCryptographicHash::hash(scene.absoluteFilePath().toUtf8(), QCryptographicHash::Sha1)
            .toHex()
            .left(kPathHashDigits);
    return userCache.filePath(QStringLiteral("scenes/%1-%2.cache")
                                  .arg(scene.completeBaseName(), QString::fromLatin1(hash)));
}

} // namespace airtrap
