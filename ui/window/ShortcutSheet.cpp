#include "window/ShortcutSheet.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>

namespace airtrap {

namespace {

//! A menu text as a name: no '&' mnemonics, no trailing "…".
QString plainText(QString text) {
    text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    text.replace(QStringLiteral("&&"), QStringLiteral("&"));
    if (text.endsWith(QChar(0x2026)))
        text.chop(1);
    return text;
}

} // namespace

ShortcutSheet::ShortcutSheet(QWidget* window)
    : QDialog(window), table_(new QTableWidget(0, 2, this)) {
    setObjectName(QStringLiteral("shortcutSheet"));
    setWindowTitle(tr("Keyboard Shortcuts"));
    table_->setObjectName(QStringLiteral("shortcutTable"));
    table_->setHorizontalHeaderLabels({tr("Keys"), tr("Action")});
    table_->verticalHeader()->hide();
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionMode(QAbstractItemView::NoSelection);
    // Every action the window owns: its own, and those made for it, as the undo stack's.
    for (const QAction* action : window->findChildren<QAction*>()) {
        QStringList keys;
        for (const QKeySequence& shortcut : action->shortcuts())
            keys << shortcut.toString(QKeySequence::NativeText);
        if (!keys.isEmpty())
            addRow(keys.join(QStringLiteral(", ")), plainText(action->text()));
    }
    // The viewport's mouse has no actions to read them from.
    addRow(tr("Left drag"), tr("Orbit the view"));
    addRow(tr("Middle drag, Shift + left drag"), tr("Pan the view"));
    addRow(tr("Wheel"), tr("Zoom toward the cursor"));
    addRow(tr("Click"), tr("Pick the object under the cursor"));
    addRow(tr("Double-click empty space"), tr("Frame all"));
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(table_);
    layout->addWidget(buttons);
    resize(560, 640);
}

void ShortcutSheet::addRow(const QString& keys, const QString& action) {
    const int row = table_->rowCount();
    table_->insertRow(row);
    table_->setItem(row, 0, new QTableWidgetItem(keys));
    table_->setItem(row, 1, new QTableWidgetItem(action));
}

} // namespace airtrap
