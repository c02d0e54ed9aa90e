#include "panels/ParameterEditor.h"

namespace airtrap {

ParameterEditor::ParameterEditor(ParameterDeclaration declaration, QWidget* parent)
    : QWidget(parent), declaration_(std::move(declaration)) {
    setObjectName(QString::fromStdString(declaration_.key));
}

} // namespace airtrap
