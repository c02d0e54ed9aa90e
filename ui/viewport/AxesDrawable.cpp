#include "viewport/AxesDrawable.h"

namespace airtrap {

namespace {

const QColor kAxisColours[3] = {QColor(230, 70, 70), QColor(100, 210, 80), QColor(70, 120, 255)};

} // namespace

AxesDrawable::AxesDrawable() {
    lines_.setWidth(2.0f);
    setLength(1.0f);
}

void AxesDrawable::setLength(float metres) {
    std::vector<LineVertex> vertices;
    for (int axis = 0; axis < 3; ++axis) {
        QVector3D tip;
        tip[axis] = metres;
        vertices.push_back(LineVertex::at(QVector3D(), kAxisColours[axis]));
        vertices.push_back(LineVertex::at(tip, kAxisColours[axis]));
    }
    lines_.setSegments(std::move(vertices));
}

} // namespace airtrap
