#pragma once
// The log dock: what the bake, the loader and file operations said, newest at the bottom, with the
// time of day. Errors are also shown as dialogs; the log keeps them after the dialog is gone.
#include <QPlainTextEdit>

namespace airtrap {

class LogPanel : public QPlainTextEdit {
    Q_OBJECT

public:
    enum class Level { Info, Warning, Error };

    explicit LogPanel(QWidget* parent = nullptr);

public Q_SLOTS:
    void info(const QString& text) { append(Level::Info, text); }
    void warning(const QString& text) { append(Level::Warning, text); }
    void error(const QString& text) { append(Level::Error, text); }
    void append(airtrap::LogPanel::Level level, const QString& text);
};

} // namespace airtrap
