#pragma once
// One parameter of the shown item in the panel's grid: its label, its editor, a reset button and,
// below them, the reason the document refused the last value. The row is the only place where a
// widget's value turns into an edit: it sends the value to SceneDocument::editParameter, shows
// the refusal and puts the document's value back, and turns a slider drag into one drag session.
#include "document/SceneItem.h"
#include "scene/ParameterDeclaration.h"

#include <QObject>
#include <string>

class QAction;
class QGridLayout;
class QLabel;
class QToolButton;

namespace airtrap {

class ParameterEditor;
class SceneDocument;

class ParameterRow : public QObject {
    Q_OBJECT

public:
    //! Adds the row for `declaration` of `item` to `grid` at `gridRow` (label, editor, reset
    //! button) and `gridRow + 1` (the refusal, hidden), and shows the document's value. The
    //! widgets and the row belong to the grid's widget.
    ParameterRow(SceneDocument& document, SceneItem item, ParameterDeclaration declaration,
                 QGridLayout& grid, int gridRow);

    //! The parameter's JSON key.
    const std::string& key() const { return declaration_.key; }
    //! The editor widget, named after the key.
    ParameterEditor* editor() const { return editor_; }

    //! Shows the document's value and forgets an earlier refusal; called when the document
    //! changed the value (an edit, undo or redo).
    void refresh();
    //! The declaration's applicability: whether this row means something for the item as it
    //! is now (a radius for a sphere, not for a box).
    bool applies() const;
    //! Shows the row's widgets, or hides them all, as applies() says.
    void showIfApplies();

private:
    QLabel* createLabel(QWidget* parent) const;
    QToolButton* createResetButton(QWidget* parent);
    QLabel* createErrorLabel(QWidget* parent) const;
    void commit(const ParameterValue& value, bool dragging);
    void startDrag();
    void finishDrag();
    void showDocumentValue();
    void showRefusal(const QString& reason);
    QString toolTip() const;
    QString withUnit(const std::string& text) const;

    SceneDocument& document_;
    SceneItem item_;
    ParameterDeclaration declaration_;
    ParameterEditor* editor_ = nullptr;
    QAction* resetAction_ = nullptr;
    QLabel* label_ = nullptr;
    QToolButton* resetButton_ = nullptr;
    QLabel* errorLabel_ = nullptr;
    //! Non-zero while a slider is held: every value of the drag merges into one undo command.
    int dragSession_ = 0;
};

} // namespace airtrap
