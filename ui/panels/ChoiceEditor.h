#pragma once
// Edits a Choice parameter with a combo box of the declared strings.
#include "panels/ParameterEditor.h"

class QComboBox;

namespace airtrap {

class ChoiceEditor : public ParameterEditor {
    Q_OBJECT

public:
    //! Builds the combo box (objectName "combo") with the declaration's choices in order.
    explicit ChoiceEditor(const ParameterDeclaration& declaration, QWidget* parent = nullptr);

    //! Selects the choice; a string that is not declared leaves the box without a selection.
    void setValue(const ParameterValue& value) override;

private:
    QComboBox* comboBox_ = nullptr;
};

} // namespace airtrap
