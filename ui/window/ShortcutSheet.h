#pragma once
// Help ▸ Keyboard Shortcuts: every action of the editor that has keys, read from the window's own
// actions (so the sheet cannot drift from what the keys do), then the mouse in the viewport.
#include <QDialog>

class QTableWidget;

namespace airtrap {

class ShortcutSheet : public QDialog {
    Q_OBJECT

public:
    //! Lists the actions `window` owns that have shortcuts.
    explicit ShortcutSheet(QWidget* window);

    //! The table, for tests: column 0 the keys, column 1 what they do.
    const QTableWidget* table() const { return table_; }

private:
    void addRow(const QString& keys, const QString& action);

    QTableWidget* table_;
};

} // namespace airtrap
