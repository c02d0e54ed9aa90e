#pragma once
// Where the editor keeps what it remembers (window layout, recent files, view options).
#include <QSettings>
#include <QTemporaryDir>
#include <memory>

namespace airtrap {

class EditorSettings {
public:
    //! The editor's settings store. Named explicitly rather than taken from QApplication so that
    //! tests, which do not set the application's names, use the same store as the editor.
    static QSettings& store() { return *current(); }

    //! From now on an empty store of its own, in a temporary folder: nothing is read from or
    //! written to the user's settings. Screenshots use it, so that a picture does not depend on
    //! how the user last left the editor and taking one changes nothing the user set.
    static void useScratchStore() {
        static QTemporaryDir folder;
        current() = std::make_unique<QSettings>(folder.filePath(QStringLiteral("editor.ini")),
                                                QSettings::IniFormat);
    }

private:
    static std::unique_ptr<QSettings>& current() {
        static std::unique_ptr<QSettings> settings =
            std::make_unique<QSettings>(QStringLiteral("Airtrap"), QStringLiteral("Airtrap"));
        return settings;
    }
};

} // namespace airtrap
