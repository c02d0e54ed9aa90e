#include "panels/CommittedFieldShortcuts.h"

#include <QKeyEvent>
#include <QLineEdit>

namespace airtrap {

namespace {

bool isHistoryKey(const QKeyEvent* key) {
    const QKeySequence pressed(key->keyCombination());
    return key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo) ||
           pressed == QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z) ||
           pressed == QKeySequence(Qt::CTRL | Qt::Key_Y);
}

} // namespace

void CommittedFieldShortcuts::install(QWidget* field, QLineEdit* lineEdit) {
    field->installEventFilter(new CommittedFieldShortcuts(field, lineEdit));
}

CommittedFieldShortcuts::CommittedFieldShortcuts(QWidget* field, QLineEdit* lineEdit)
    : QObject(field), lineEdit_(lineEdit) {}

bool CommittedFieldShortcuts::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::ShortcutOverride)
        return QObject::eventFilter(watched, event);
    // setText() (the document's value shown) clears isModified(); typing sets it.
    if (!isHistoryKey(static_cast<QKeyEvent*>(event)) || lineEdit_->isModified())
        return QObject::eventFilter(watched, event);
    // Ignored, the override lets the shortcut map give the keys to the Undo and Redo actions.
    event->ignore();
    return true;
}

} // namespace airtrap
