#pragma once
// The scene being edited: the Scene (plain engine data), the file it came from, and the undo stack
// every edit goes through. Widgets never change the Scene directly: they call the edit functions
// below, which check the value against its declaration and push an undo command; the commands call
// the apply/insert/erase functions, which change the Scene and emit the signals views follow.
#include "commands/SetParameterCommand.h"
#include "document/SceneItem.h"
#include "scene/ParameterDeclaration.h"
#include "scene/Scene.h"

#include <QObject>
#include <QString>
#include <nlohmann/json.hpp>
#include <string>

class QUndoStack;

namespace airtrap {

struct SchemaSection;
struct BoundParameter;

class SceneDocument : public QObject {
    Q_OBJECT

public:
    explicit SceneDocument(QObject* parent = nullptr);

    const Scene& scene() const { return scene_; }
    QUndoStack* undoStack() const { return undoStack_; }

    //! The file the scene was opened from or saved to; empty for a new scene.
    QString filePath() const { return filePath_; }
    //! The file's name, or "Untitled" — for the window title.
    QString displayName() const;
    //! True when there are edits since the last open, new or save.
    bool isModified() const;

    // --- Whole documents. Each clears the undo history and emits aboutToReset/reset. ----------

    //! A new scene: a 1 m tank with one block of water, ready to bake.
    void newScene();
    //! Reads and checks the file (engine's readSceneFile). Throws airtrap::Error, whose message
    //! names the file, the JSON path, the value and the allowed range; the document is unchanged.
    void open(const QString& path);
    //! Makes `scene` the document, with no file (e.g. the scene copy in a cache's manifest).
    void adoptScene(Scene scene);
    //! Writes the scene atomically to `path` and makes it the document's file. Throws Error(Io).
    void save(const QString& path);

    // --- Edits: each checks, then pushes one undo command. --------------------------------------

    //! Sets a parameter of a section or element. Returns the reason when the value is refused
    //! (the declaration's range, choices, length), with nothing changed; an empty string when it
    //! was applied. Edits with the same non-zero `dragSession` to the same parameter merge into
    //! one undo command (a slider drag is one command); 0 never merges.
    QString editParameter(const SceneItem& item, const std::string& key,
                          const ParameterValue& value, int dragSession = 0);
    //! Sets several parameters of one item as one undo step named `text` (a move changes both
    //! corners of a fluid block); merges with the previous step of the same `dragSession` and
    //! keys. Returns the first refusal, with nothing changed.
    QString editParameters(const SceneItem& item,
                           const std::vector<std::pair<std::string, ParameterValue>>& values,
                           int dragSession, const QString& text);
    //! A fresh number for editParameter's dragSession.
    int newDragSession() { return ++lastDragSession_; }

    //! Appends a default element to an array section; returns it.
    SceneItem addElement(const std::string& section);
    //! Appends an element whose `values` (a JSON object of the section's keys) replace the
    //! defaults, as one undo step named `text`; returns it. Values are trusted, as for
    //! insertElement: callers build them from the schema's own keys.
    SceneItem addElement(const std::string& section, const nlohmann::json& values,
                         const QString& text);
    //! Inserts a copy of an element after it, named "<name> copy"; returns the copy.
    SceneItem duplicateElement(const SceneItem& item);
    //! Removes an element.
    void removeElement(const SceneItem& item);
    //! Renames an element (its "name" parameter); returns the reason when refused.
    QString renameElement(const SceneItem& item, const QString& name);

    // --- Reading items. --------------------------------------------------------------------------

    ParameterValue parameter(const SceneItem& item, const std::string& key) const;
    //! The element's "name" parameter, or its section's element label and number.
    QString elementName(const SceneItem& item) const;
    //! True when the item exists in the current scene (element index in range, section known).
    bool contains(const SceneItem& item) const;
    //! "solver.fps", "fluid_blocks[1].max": the item's parameter path as messages print it.
    static std::string pathOf(const SceneItem& item, const std::string& key);

    // --- Raw changes, for undo commands only: no checks, no undo entry, signals emitted. -------

    void applyParameter(const SceneItem& item, const std::string& key, const ParameterValue& value);
    //! Inserts an element given as its JSON object (keys of the section) before `index`.
    void insertElement(const std::string& section, std::size_t index,
                       const nlohmann::json& element);
    void eraseElement(const std::string& section, std::size_t index);
    //! An element as a JSON object with every declared key.
    nlohmann::json elementJson(const std::string& section, std::size_t index) const;

    //! The schema section of `key`; throws Error(InvalidInput) for an unknown one.
    static const SchemaSection& sectionOf(const std::string& key);

Q_SIGNALS:
    void parameterChanged(const airtrap::SceneItem& item, const QString& key);
    void elementAboutToBeInserted(const QString& section, int index);
    void elementInserted(const QString& section, int index);
    void elementAboutToBeRemoved(const QString& section, int index);
    void elementRemoved(const QString& section, int index);
    //! Before and after the whole scene is replaced (new, open, adopt); no changed() follows.
    void aboutToReset();
    void reset();
    //! After an edit of the scene's content: a parameter, an insert or a removal, or their undo
    //! and redo.
    void changed();
    void filePathChanged(const QString& path);
    void modifiedChanged(bool modified);

private:
    void replaceScene(Scene scene, const QString& path);
    const BoundParameter& boundParameter(const SceneItem& item, const std::string& key) const;
    //! The change `value` makes to `key` of `item` (normalised to the declaration's kind), or the
    //! reason it is refused (the item is gone, the value out of range).
    QString checkedChange(const SceneItem& item, const std::string& key,
                          const ParameterValue& value, ParameterChange& change) const;

    Scene scene_;
    QString filePath_;
    QUndoStack* undoStack_ = nullptr;
    int lastDragSession_ = 0;
};

} // namespace airtrap
