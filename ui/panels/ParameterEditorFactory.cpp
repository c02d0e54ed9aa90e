#include "panels/ParameterEditorFactory.h"

#include "core/Error.h"
#include "panels/BoolEditor.h"
#include "panels/ChoiceEditor.h"
#include "panels/IntEditor.h"
#include "panels/RealEditor.h"
#include "panels/StringEditor.h"
#include "panels/Vector3Editor.h"

namespace airtrap {

ParameterEditor* ParameterEditorFactory::create(const ParameterDeclaration& declaration,
                                                QWidget* parent) {
    switch (declaration.kind) {
    case ParameterKind::Bool:
        return new BoolEditor(declaration, parent);
    case ParameterKind::Int:
        return new IntEditor(declaration, parent);
    case ParameterKind::Real:
        return new RealEditor(declaration, parent);
    case ParameterKind::Vector3:
        return new Vector3Editor(declaration, parent);
    case ParameterKind::String:
        return new StringEditor(declaration, parent);
    case ParameterKind::Choice:
        return new ChoiceEditor(declaration, parent);
    }
    throw Error(ErrorKind::InvalidInput,
                "parameter " + declaration.key + " has a kind the editor does not know");
}

} // namespace airtrap
