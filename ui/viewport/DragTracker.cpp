#include "viewport/DragTracker.h"

#include <QLineF>

namespace airtrap {

void DragTracker::press(const QPointF& position, Qt::MouseButton button,
                        Qt::KeyboardModifiers modifiers) {
    pressPosition_ = position;
    lastPosition_ = position;
    button_ = button;
    dragging_ = false;
    if (button == Qt::MiddleButton || (button == Qt::LeftButton && modifiers & Qt::ShiftModifier)) {
        mode_ = Mode::Pan;
    } else if (button == Qt::LeftButton) {
        mode_ = Mode::Orbit;
    } else {
        mode_ = Mode::None;
    }
}

std::optional<QPointF> DragTracker::move(const QPointF& position) {
    if (button_ == Qt::NoButton) {
        return std::nullopt;
    }
    if (!dragging_) {
        if (QLineF(pressPosition_, position).length() <= kClickSlop) {
            return std::nullopt;
        }
        dragging_ = true;
    }
    const QPointF delta = position - lastPosition_;
    lastPosition_ = position;
    return delta;
}

bool DragTracker::release(Qt::MouseButton button) {
    if (button != button_) {
        return false;
    }
    const bool click = button == Qt::LeftButton && !dragging_;
    button_ = Qt::NoButton;
    mode_ = Mode::None;
    dragging_ = false;
    return click;
}

void DragTracker::cancel() {
    // Counted as a drag from the start: its release is no click, yet moving still navigates.
    dragging_ = true;
}

} // namespace airtrap
