#include "panels/ChoiceEditor.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QSignalBlocker>

namespace airtrap {

ChoiceEditor::ChoiceEditor(const ParameterDeclaration& declaration, QWidget* parent)
    : ParameterEditor(declaration, parent), comboBox_(new QComboBox(this)) {
    comboBox_->setObjectName(QStringLiteral("combo"));
    for (const std::string& choice : declaration.choices)
        comboBox_->addItem(QString::fromStdString(choice));
    // activated, not currentIndexChanged: only the user's picks are edits, not setValue().
    connect(comboBox_, &QComboBox::activated, this,
            [this](int index) { Q_EMIT edited(comboBox_->itemText(index).toStdString(), false); });
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(comboBox_);
    setFocusProxy(comboBox_);
}

void ChoiceEditor::setValue(const ParameterValue& value) {
    const QSignalBlocker blocker(comboBox_);
    comboBox_->setCurrentIndex(
        comboBox_->findText(QString::fromStdString(std::get<std::string>(value))));
}

} // namespace airtrap
