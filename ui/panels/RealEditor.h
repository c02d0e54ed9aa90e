#pragma once
// Edits a Real parameter: a number field, plus a slider when the declared range is finite and
// narrow enough to drag through.
#include "panels/ParameterEditor.h"
#include "panels/SliderScale.h"

#include <optional>

class QSlider;

namespace airtrap {

class NumberField;

class RealEditor : public ParameterEditor {
    Q_OBJECT

public:
    //! Builds the field (objectName "field") and, when the range allows, the slider ("slider").
    explicit RealEditor(const ParameterDeclaration& declaration, QWidget* parent = nullptr);

    //! Shows the number; the slider follows unless the user is dragging it.
    void setValue(const ParameterValue& value) override;

private:
    QSlider* createSlider(const SliderScale& scale);
    void onSliderMoved(int position);

    NumberField* field_ = nullptr;
    QSlider* slider_ = nullptr;
    std::optional<SliderScale> scale_;
};

} // namespace airtrap
