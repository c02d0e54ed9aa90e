#include "commands/SetParameterCommand.h"

#include "document/SceneDocument.h"

namespace airtrap {

namespace {
// QUndoStack only offers mergeWith() between commands of equal id.
constexpr int kSetParameterCommandId = 0x5e7;
} // namespace

SetParameterCommand::SetParameterCommand(SceneDocument& document, SceneItem item, std::string key,
                                         ParameterValue oldValue, ParameterValue newValue,
                                         int dragSession, const QString& text)
    : QUndoCommand(text), document_(document), item_(std::move(item)), key_(std::move(key)),
      oldValue_(std::move(oldValue)), newValue_(std::move(newValue)), dragSession_(dragSession) {}

void SetParameterCommand::undo() {
    document_.applyParameter(item_, key_, oldValue_);
}

void SetParameterCommand::redo() {
    document_.applyParameter(item_, key_, newValue_);
}

int SetParameterCommand::id() const {
    return dragSession_ == 0 ? -1 : kSetParameterCommandId;
}

bool SetParameterCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const SetParameterCommand*>(other);
    if (next == nullptr || next->dragSession_ != dragSession_ || next->item_ != item_ ||
        next->key_ != key_)
        return false;
    // The merged command undoes to the value before the drag and redoes to its last value, which
    // its history line names.
    newValue_ = next->newValue_;
    setText(next->text());
    return true;
}

} // namespace airtrap
