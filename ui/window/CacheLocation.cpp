#include "window/CacheLocation.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace airtrap {

QString CacheLocation::forScene(const QString& scenePath) {
    if (scenePath.isEmpty())
        return QDir(QStandardPaths::writableLocation(QStandardPaths::CacheLocation))
            .filePath(QStringLiteral("untitled.cache"));
    const QFileInfo scene(scenePath);
    return scene.absoluteDir().filePath(scene.completeBaseName() + QStringLiteral(".cache"));
}

} // namespace airtrap
