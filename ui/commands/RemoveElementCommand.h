#pragma once
// Removes an element from an array section, keeping all of it for Undo.
#include <QUndoCommand>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace airtrap {

class SceneDocument;

class RemoveElementCommand : public QUndoCommand {
public:
    RemoveElementCommand(SceneDocument& document, std::string section, std::size_t index,
                         const QString& text);

    void undo() override;
    void redo() override;

private:
    SceneDocument& document_;
    std::string section_;
    std::size_t index_;
    nlohmann::json removed_; //!< the element as it was, filled on redo
};

} // namespace airtrap
