#pragma once
// Adds an element (fluid block, obstacle, …) to an array section: a new one, or a duplicate.
#include <QUndoCommand>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace airtrap {

class SceneDocument;

class InsertElementCommand : public QUndoCommand {
public:
    //! Inserts `element` (a JSON object with the section's keys) before `index`.
    InsertElementCommand(SceneDocument& document, std::string section, std::size_t index,
                         nlohmann::json element, const QString& text);

    void undo() override;
    void redo() override;

private:
    SceneDocument& document_;
    std::string section_;
    std::size_t index_;
    nlohmann::json element_;
};

} // namespace airtrap
