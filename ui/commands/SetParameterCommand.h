#pragma once
// One parameter edit. Edits made during one slider drag share a drag session and merge into a
// single command, so one drag is one step of Undo.
#include "document/SceneItem.h"
#include "scene/ParameterDeclaration.h"

#include <QUndoCommand>
#include <string>

namespace airtrap {

class SceneDocument;

class SetParameterCommand : public QUndoCommand {
public:
    //! `text` is shown in History ("Set Cube density to 2000 kg/m³"); `dragSession` 0 never merges.
    SetParameterCommand(SceneDocument& document, SceneItem item, std::string key,
                        ParameterValue oldValue, ParameterValue newValue, int dragSession,
                        const QString& text);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    SceneDocument& document_;
    SceneItem item_;
    std::string key_;
    ParameterValue oldValue_;
    ParameterValue newValue_;
    int dragSession_;
};

} // namespace airtrap
