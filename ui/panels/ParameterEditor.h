#pragma once
// The widget that edits one parameter of one kind. It only reports what the user chose: the
// ParameterRow around it sends the value to the document, which may refuse it, and then shows the
// document's value again through setValue(). An editor never decides what is allowed.
#include "scene/ParameterDeclaration.h"

#include <QWidget>

namespace airtrap {

class ParameterEditor : public QWidget {
    Q_OBJECT

public:
    //! An editor for `declaration`, named after its key (objectName "particle_spacing").
    explicit ParameterEditor(ParameterDeclaration declaration, QWidget* parent = nullptr);

    //! Shows `value`, which holds the declaration's kind, without emitting edited(). A slider
    //! being dragged keeps its position; the number beside it follows.
    virtual void setValue(const ParameterValue& value) = 0;

    //! The declaration this editor was made for.
    const ParameterDeclaration& declaration() const { return declaration_; }

Q_SIGNALS:
    //! The user chose `value`. `dragging` is true for the live values of a slider drag, which
    //! arrive between dragStarted() and dragFinished() and make up one undo step.
    void edited(const airtrap::ParameterValue& value, bool dragging);
    //! The user grabbed a slider.
    void dragStarted();
    //! The user let go of the slider.
    void dragFinished();

private:
    ParameterDeclaration declaration_;
};

} // namespace airtrap
