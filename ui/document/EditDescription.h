#pragma once
// The line the History panel and Edit ▸ Undo show for a parameter edit. It names the object, the
// parameter, the new value and its unit ("Set Cube density to 2000 kg/m³"), so a user scanning the
// history can tell two edits of one field apart without undoing them to look.
#include "scene/ParameterDeclaration.h"

#include <QString>

namespace airtrap {

class EditDescription {
public:
    //! "Set <owner> <label> to <value> <unit>"; `owner` is the element's name or the section's
    //! label ("Cube", "Solver").
    static QString ofParameter(const QString& owner, const ParameterDeclaration& declaration,
                               const ParameterValue& value);

private:
    static QString labelInSentence(const std::string& label);
    static QString valueText(const ParameterDeclaration& declaration, const ParameterValue& value);
};

} // namespace airtrap
