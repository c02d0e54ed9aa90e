#pragma once
// Edits a Bool parameter with a check box.
#include "panels/ParameterEditor.h"

class QCheckBox;

namespace airtrap {

class BoolEditor : public ParameterEditor {
    Q_OBJECT

public:
    //! Builds the check box (objectName "check").
    explicit BoolEditor(const ParameterDeclaration& declaration, QWidget* parent = nullptr);

    //! Ticks the box for true.
    void setValue(const ParameterValue& value) override;

private:
    QCheckBox* checkBox_ = nullptr;
};

} // namespace airtrap
