#include "panels/IntEditor.h"

#include "panels/NumberField.h"

#include <QHBoxLayout>
#include <cmath>

namespace airtrap {

IntEditor::IntEditor(const ParameterDeclaration& declaration, QWidget* parent)
    : ParameterEditor(declaration, parent), field_(new NumberField(true, this)) {
    field_->setObjectName(QStringLiteral("field"));
    connect(field_, &NumberField::committed, this, [this](double number) {
        Q_EMIT edited(static_cast<long long>(std::llround(number)), false);
    });
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(field_);
    setFocusProxy(field_);
}

void IntEditor::setValue(const ParameterValue& value) {
    field_->setNumber(static_cast<double>(std::get<long long>(value)));
}

} // namespace airtrap
