#include "window/LogPanel.h"

#include <QTime>

namespace airtrap {

namespace {
// A long bake logs a line per message, not per frame; this keeps days of it without slowing down.
constexpr int kMaximumLines = 5000;
} // namespace

LogPanel::LogPanel(QWidget* parent) : QPlainTextEdit(parent) {
    setReadOnly(true);
    setMaximumBlockCount(kMaximumLines);
    setLineWrapMode(QPlainTextEdit::WidgetWidth);
    setObjectName(QStringLiteral("logPanel"));
}

void LogPanel::append(Level level, const QString& text) {
    const QString time = QTime::currentTime().toString(QStringLiteral("HH:mm:ss"));
    QString prefix;
    if (level == Level::Warning)
        prefix = tr("warning: ");
    else if (level == Level::Error)
        prefix = tr("error: ");
    appendPlainText(QStringLiteral("%1  %2%3").arg(time, prefix, text));
}

} // namespace airtrap
