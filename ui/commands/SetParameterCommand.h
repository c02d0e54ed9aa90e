#pragma once
// One edit of one or more parameters of an item: a typed value, or a move that changes a body's
// position or both corners of a fluid block at once. Edits made during one drag (a slider, the
// move gizmo) share a drag session and merge into a single command, so one drag is one step of
// Undo.
#include "document/SceneItem.h"
#include "scene/ParameterDeclaration.h"

#include <QUndoCommand>
#include <string>
#include <vector>

namespace airtrap {

class SceneDocument;

//! A parameter's value before and after an edit.
struct ParameterChange {
    std::string key;
    ParameterValue oldValue;
    ParameterValue newValue;
};

class SetParameterCommand : public QUndoCommand {
public:
    //! `text` is shown in History ("Set Cube density to 2000 kg/m³"); `dragSession` 0 never
    //! merges.
    SetParameterCommand(SceneDocument& document, SceneItem item,
                        std::vector<ParameterChange> changes, int dragSession, const QString& text);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    bool changesSameKeys(const SetParameterCommand& other) const;

    SceneDocument& document_;
    SceneItem item_;
    std::vector<ParameterChange> changes_;
    int dragSession_;
};

} // namespace airtrap
