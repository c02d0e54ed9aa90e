#pragma once
// Picks the editor widget for a parameter from its declared kind. This switch is the only place
// that knows which widget edits which kind; no code anywhere names a particular parameter.
#include "scene/ParameterDeclaration.h"

class QWidget;

namespace airtrap {

class ParameterEditor;

class ParameterEditorFactory {
public:
    //! A new editor for `declaration`, owned by `parent`.
    static ParameterEditor* create(const ParameterDeclaration& declaration, QWidget* parent);
};

} // namespace airtrap
