#include "panels/BoolEditor.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QSignalBlocker>

namespace airtrap {

BoolEditor::BoolEditor(const ParameterDeclaration& declaration, QWidget* parent)
    : ParameterEditor(declaration, parent), checkBox_(new QCheckBox(this)) {
    checkBox_->setObjectName(QStringLiteral("check"));
    // clicked, not toggled: only the user's clicks are edits, not setValue().
    connect(checkBox_, &QCheckBox::clicked, this,
            [this](bool checked) { Q_EMIT edited(checked, false); });
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(checkBox_);
    setFocusProxy(checkBox_);
}

void BoolEditor::setValue(const ParameterValue& value) {
    const QSignalBlocker blocker(checkBox_);
    checkBox_->setChecked(std::get<bool>(value));
}

} // namespace airtrap
