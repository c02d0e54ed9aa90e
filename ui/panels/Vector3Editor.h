#pragma once
// Edits a Vector3 parameter with one number field per axis. Each field commits its component on
// its own; the vector sent is the document's with that component replaced.
#include "panels/ParameterEditor.h"

#include <array>

namespace airtrap {

class NumberField;

class Vector3Editor : public ParameterEditor {
    Q_OBJECT

public:
    //! Builds the fields, named "x", "y" and "z".
    explicit Vector3Editor(const ParameterDeclaration& declaration, QWidget* parent = nullptr);

    //! Shows the three components.
    void setValue(const ParameterValue& value) override;

private:
    void onComponentCommitted(int axis, double number);

    std::array<NumberField*, 3> fields_{};
    Vec3d shown_ = Vec3d::Zero();
};

} // namespace airtrap
