#pragma once
// Where the editor bakes a scene: "<folder of the scene>/<file name without .json>.cache", so a
// scene and its frames travel together. A scene in a folder the user cannot write (an installed
// samples folder) bakes into a folder of its own in the user's cache location instead, and so
// does an unsaved scene.
#include <QString>
#include <functional>

namespace airtrap {

class CacheLocation {
public:
    //! Answers whether files can be created in a folder.
    using WritableTest = std::function<bool(const QString& folder)>;

    CacheLocation();

    //! Beside the scene when its folder can be written, else perUser(scenePath).
    QString forScene(const QString& scenePath) const;
    //! True when the scene is saved and its folder can be written.
    bool canBakeBeside(const QString& scenePath) const;

    //! "<scene folder>/<name>.cache".
    static QString besideScene(const QString& scenePath);
    //! "<user cache>/scenes/<name>-<8 hex digits of the scene's path>.cache": the same folder
    //! every time the scene is opened, and one per scene of the same name; "untitled.cache" for
    //! an unsaved scene.
    static QString perUser(const QString& scenePath);

    //! Tests replace the check: root, who runs them, can write anywhere.
    void setWritableTest(WritableTest test) { writable_ = std::move(test); }

private:
    WritableTest writable_;
};

} // namespace airtrap
