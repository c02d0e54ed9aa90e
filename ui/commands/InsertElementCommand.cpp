#include "commands/InsertElementCommand.h"

#include "document/SceneDocument.h"

namespace airtrap {

InsertElementCommand::InsertElementCommand(SceneDocument& document, std::string section,
                                           std::size_t index, nlohmann::json element,
                                           const QString& text)
    : QUndoCommand(text), document_(document), section_(std::move(section)), index_(index),
      element_(std::move(element)) {}

void InsertElementCommand::undo() {
    document_.eraseElement(section_, index_);
}

void InsertElementCommand::redo() {
    document_.insertElement(section_, index_, element_);
}

} // namespace airtrap
