#include "commands/RemoveElementCommand.h"

#include "document/SceneDocument.h"

namespace airtrap {

RemoveElementCommand::RemoveElementCommand(SceneDocument& document, std::string section,
                                           std::size_t index, const QString& text)
    : QUndoCommand(text), document_(document), section_(std::move(section)), index_(index) {}

void RemoveElementCommand::undo() {
    document_.insertElement(section_, index_, removed_);
}

void RemoveElementCommand::redo() {
    removed_ = document_.elementJson(section_, index_);
    document_.eraseElement(section_, index_);
}

} // namespace airtrap
