#include "panels/StringEditor.h"

#include "panels/CommittedFieldShortcuts.h"

#include <QHBoxLayout>
#include <QLineEdit>
#include <QSignalBlocker>

namespace airtrap {

StringEditor::StringEditor(const ParameterDeclaration& declaration, QWidget* parent)
    : ParameterEditor(declaration, parent), lineEdit_(new QLineEdit(this)) {
    lineEdit_->setObjectName(QStringLiteral("text"));
    connect(lineEdit_, &QLineEdit::editingFinished, this, &StringEditor::commitText);
    CommittedFieldShortcuts::install(lineEdit_, lineEdit_);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(lineEdit_);
    setFocusProxy(lineEdit_);
}

void StringEditor::setValue(const ParameterValue& value) {
    shown_ = QString::fromStdString(std::get<std::string>(value));
    const QSignalBlocker blocker(lineEdit_);
    lineEdit_->setText(shown_);
}

void StringEditor::commitText() {
    // Blanks around a name are typing accidents; an all-blank name is then refused as empty.
    const QString text = lineEdit_->text().trimmed();
    if (text == shown_) {
        setValue(shown_.toStdString());
        return;
    }
    Q_EMIT edited(text.toStdString(), false);
}

} // namespace airtrap
