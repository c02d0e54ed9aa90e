#include "panels/RealEditor.h"

#include "panels/NumberField.h"

#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>

namespace airtrap {

namespace {
//! The field shares the row with the slider but must keep room for about ten digits.
constexpr int kNumberFieldMinimumWidth = 90;
} // namespace

RealEditor::RealEditor(const ParameterDeclaration& declaration, QWidget* parent)
    : ParameterEditor(declaration, parent), field_(new NumberField(false, this)),
      scale_(SliderScale::forDeclaration(declaration)) {
    field_->setObjectName(QStringLiteral("field"));
    field_->setMinimumWidth(kNumberFieldMinimumWidth);
    connect(field_, &NumberField::committed, this,
            [this](double number) { Q_EMIT edited(number, false); });

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    if (scale_) {
        slider_ = createSlider(*scale_);
        layout->addWidget(slider_, 1);
    }
    layout->addWidget(field_, scale_ ? 0 : 1);
    setFocusProxy(field_);
}

QSlider* RealEditor::createSlider(const SliderScale& scale) {
    auto* slider = new QSlider(Qt::Horizontal, this);
    slider->setObjectName(QStringLiteral("slider"));
    slider->setRange(scale.firstPosition(), scale.lastPosition());
    // The field holds the exact number; keyboard focus on the slider would only steal it.
    slider->setFocusPolicy(Qt::NoFocus);
    connect(slider, &QSlider::sliderPressed, this, &ParameterEditor::dragStarted);
    connect(slider, &QSlider::valueChanged, this, &RealEditor::onSliderMoved);
    connect(slider, &QSlider::sliderReleased, this, &ParameterEditor::dragFinished);
    return slider;
}

void RealEditor::setValue(const ParameterValue& value) {
    const double number = std::get<double>(value);
    field_->setNumber(number);
    // Moving the handle under the user's mouse would make it jump between the rounded value and
    // the pointer.
    if (slider_ != nullptr && !slider_->isSliderDown()) {
        const QSignalBlocker blocker(slider_);
        slider_->setValue(scale_->positionOf(number));
    }
}

void RealEditor::onSliderMoved(int position) {
    // Clicks in the groove and the mouse wheel move the slider without a drag: one edit each.
    Q_EMIT edited(scale_->valueAt(position), slider_->isSliderDown());
}

} // namespace airtrap
