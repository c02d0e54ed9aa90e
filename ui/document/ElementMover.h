#pragma once
// Moves an object of the scene along a world axis, as the viewport's move gizmo drags it: a body,
// an obstacle or an emitter by its position, a fluid block by both its corners. The values of a
// drag are offsets from where the object stood when the drag began, so rounding never drifts, and
// the whole drag is one undo step ("Move Cube along x by 0.12 m").
#include "core/Math.h"
#include "document/SceneItem.h"

#include <QString>
#include <string>
#include <utility>
#include <vector>

namespace airtrap {

class SceneDocument;

class ElementMover {
public:
    explicit ElementMover(SceneDocument& document) : document_(document) {}

    //! The position parameters a move changes; empty for what cannot be moved (the container,
    //! whole sections, keyframes).
    static std::vector<std::string> positionKeys(const SceneItem& item);
    static bool canMove(const SceneItem& item) { return !positionKeys(item).empty(); }

    //! A drag of `item` begins: its positions now are where offsets count from.
    void begin(const SceneItem& item);
    //! Puts the item `offset` metres along world axis `axis` (0 x, 1 y, 2 z) from where it was at
    //! begin(). Returns the document's refusal (a position out of range), with nothing changed.
    QString moveTo(int axis, double offset);
    //! The drag ended: the next begin() starts a new undo step.
    void end();
    bool isMoving() const { return session_ != 0; }

private:
    SceneDocument& document_;
    SceneItem item_;
    int session_ = 0;
    std::vector<std::pair<std::string, Vec3d>> origin_;
};

} // namespace airtrap
