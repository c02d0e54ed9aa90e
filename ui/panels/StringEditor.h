#pragma once
// Edits a String parameter in a line edit, committed on Enter or when the field loses focus (not
// on every keystroke, which would make each letter an undo step).
#include "panels/ParameterEditor.h"

class QLineEdit;

namespace airtrap {

class StringEditor : public ParameterEditor {
    Q_OBJECT

public:
    //! Builds the line edit (objectName "text").
    explicit StringEditor(const ParameterDeclaration& declaration, QWidget* parent = nullptr);

    //! Shows the text.
    void setValue(const ParameterValue& value) override;

private:
    void commitText();

    QLineEdit* lineEdit_ = nullptr;
    QString shown_;
};

} // namespace airtrap
