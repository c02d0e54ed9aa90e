#pragma once
// Edits an Int parameter in a number field that takes whole numbers only. The field holds them
// as doubles, exact up to 2^53, which is the largest declared maximum (the random seed).
#include "panels/ParameterEditor.h"

namespace airtrap {

class NumberField;

class IntEditor : public ParameterEditor {
    Q_OBJECT

public:
    //! Builds the field (objectName "field").
    explicit IntEditor(const ParameterDeclaration& declaration, QWidget* parent = nullptr);

    //! Shows the integer.
    void setValue(const ParameterValue& value) override;

private:
    NumberField* field_ = nullptr;
};

} // namespace airtrap
