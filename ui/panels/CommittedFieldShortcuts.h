#pragma once
// Lets Undo and Redo reach the editor's history while a parameter field has the focus. A line
// edit claims Ctrl+Z and Ctrl+Shift+Z for its own typing history (ShortcutOverride), so after
// the user typed a value and pressed Enter, Ctrl+Z would undo the typing inside the field instead
// of the edit. Once the field shows the document's value again (nothing typed since), the keys
// belong to the document; while the user is typing, they still undo the typing.
#include <QObject>

class QLineEdit;

namespace airtrap {

class CommittedFieldShortcuts : public QObject {
    Q_OBJECT

public:
    //! Watches `field` (the widget that receives the key events: the line edit itself, or the spin
    //! box around it) whose text is in `lineEdit`; owned by `field`.
    static void install(QWidget* field, QLineEdit* lineEdit);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    CommittedFieldShortcuts(QWidget* field, QLineEdit* lineEdit);

    QLineEdit* lineEdit_;
};

} // namespace airtrap
