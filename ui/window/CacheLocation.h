#pragma once
// Where the editor bakes a scene: "<folder of the scene>/<file name without .json>.cache", so a
// scene and its frames travel together; an unsaved scene bakes into the user's cache folder.
#include <QString>

namespace airtrap {

class CacheLocation {
public:
    //! `scenePath` empty: the unsaved scene's folder in QStandardPaths::CacheLocation.
    static QString forScene(const QString& scenePath);
};

} // namespace airtrap
