#pragma once
// Tells clicks from drags for the viewport's mouse: a press becomes a drag (orbit or pan) only
// once the cursor has moved a few pixels, so that a slightly shaky click still picks and a drag
// never picks. Left drags orbit; middle drags and shift + left drags pan.
#include <QPointF>
#include <Qt>
#include <optional>

namespace airtrap {

class DragTracker {
public:
    enum class Mode {
        None,  //!< no button held, or a button that does nothing
        Orbit, //!< left button
        Pan,   //!< middle button, or shift + left
    };

    //! Pixels the cursor may move between press and release for the press to stay a click.
    static constexpr double kClickSlop = 4.0;

    //! Starts tracking a button press at `position` (widget pixels).
    void press(const QPointF& position, Qt::MouseButton button, Qt::KeyboardModifiers modifiers);
    //! The cursor moved: the movement since the last step of the drag, once the press has turned
    //! into a drag; nothing while it is still a click (or no button is held).
    std::optional<QPointF> move(const QPointF& position);
    //! Ends the press; true when it was a click of the left button.
    bool release(Qt::MouseButton button);
    //! Makes the current press no click (the second press of a double-click); it may still drag.
    void cancel();

    //! What a drag of the current press does.
    Mode mode() const { return mode_; }
    //! True once the current press has moved past the click slop.
    bool isDragging() const { return dragging_; }

private:
    QPointF pressPosition_;
    QPointF lastPosition_;
    Qt::MouseButton button_ = Qt::NoButton;
    Mode mode_ = Mode::None;
    bool dragging_ = false;
};

} // namespace airtrap
