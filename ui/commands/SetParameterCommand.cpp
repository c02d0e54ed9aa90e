#include "commands/SetParameterCommand.h"

#include "document/SceneDocument.h"

namespace airtrap {

namespace {
// QUndoStack only offers mergeWith() between commands of equal id.
constexpr int kSetParameterCommandId = 0x5e7;
} // namespace

SetParameterCommand::SetParameterCommand(SceneDocument& document, SceneItem item,
                                         std::vector<ParameterChange> changes, int dragSession,
                                         const QString& text)
    : QUndoCommand(text), document_(document), item_(std::move(item)), changes_(std::move(changes)),
      dragSession_(dragSession) {}

void SetParameterCommand::undo() {
    for (auto change = changes_.rbegin(); change != changes_.rend(); ++change)
        document_.applyParameter(item_, change->key, change->oldValue);
}

void SetParameterCommand::redo() {
    for (const ParameterChange& change : changes_)
        document_.applyParameter(item_, change.key, change.newValue);
}

int SetParameterCommand::id() const {
    return dragSession_ == 0 ? -1 : kSetParameterCommandId;
}

bool SetParameterCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const SetParameterCommand*>(other);
    if (next == nullptr || next->dragSession_ != dragSession_ || next->item_ != item_ ||
        !changesSameKeys(*next))
        return false;
    // The merged command undoes to the values before the drag and redoes to its last values,
    // which its history line names.
    for (std::size_t i = 0; i < changes_.size(); ++i)
        changes_[i].newValue = next->changes_[i].newValue;
    setText(next->text());
    return true;
}

bool SetParameterCommand::changesSameKeys(const SetParameterCommand& other) const {
    if (other.changes_.size() != changes_.size())
        return false;
    for (std::size_t i = 0; i < changes_.size(); ++i)
        if (other.changes_[i].key != changes_[i].key)
            return false;
    return true;
}

} // namespace airtrap
