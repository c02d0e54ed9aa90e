#include "panels/Vector3Editor.h"

#include "panels/NumberField.h"

#include <QHBoxLayout>
#include <QLabel>

namespace airtrap {

namespace {
//! Three fields share one row; each still needs room for a number like -12.345.
constexpr int kComponentFieldMinimumWidth = 60;
} // namespace

Vector3Editor::Vector3Editor(const ParameterDeclaration& declaration, QWidget* parent)
    : ParameterEditor(declaration, parent) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    const std::array<QString, 3> axisNames{QStringLiteral("x"), QStringLiteral("y"),
                                           QStringLiteral("z")};
    for (int axis = 0; axis < 3; ++axis) {
        auto* field = new NumberField(false, this);
        field->setObjectName(axisNames[axis]);
        field->setMinimumWidth(kComponentFieldMinimumWidth);
        field->setToolTip(axisNames[axis]);
        connect(field, &NumberField::committed, this,
                [this, axis](double number) { onComponentCommitted(axis, number); });
        auto* axisLabel = new QLabel(axisNames[axis], this);
        axisLabel->setBuddy(field);
        layout->addWidget(axisLabel);
        layout->addWidget(field, 1);
        fields_[axis] = field;
    }
    setFocusProxy(fields_[0]);
}

void Vector3Editor::setValue(const ParameterValue& value) {
    shown_ = std::get<Vec3d>(value);
    for (int axis = 0; axis < 3; ++axis)
        fields_[axis]->setNumber(shown_[axis]);
}

void Vector3Editor::onComponentCommitted(int axis, double number) {
    Vec3d vector = shown_;
    vector[axis] = number;
    Q_EMIT edited(vector, false);
}

} // namespace airtrap
