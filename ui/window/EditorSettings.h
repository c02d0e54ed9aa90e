#pragma once
// Where the editor keeps what it remembers (window layout, recent files, view options).
#include <QSettings>

namespace airtrap {

class EditorSettings {
public:
    //! The editor's settings store. Named explicitly rather than taken from QApplication so that
    //! tests, which do not set the application's names, use the same store as the editor.
    static QSettings& store() {
        static QSettings settings(QStringLiteral("Airtrap"), QStringLiteral("Airtrap"));
        return settings;
    }
};

} // namespace airtrap
