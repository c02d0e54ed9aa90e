#pragma once
// One end of a line segment as uploaded to the GPU: position and straight-alpha colour.
#include <QColor>
#include <QVector3D>
#include <QVector4D>

namespace airtrap {

struct LineVertex {
    QVector3D position; //!< m, world space
    QVector4D colour;   //!< red, green, blue, alpha in [0, 1]

    //! A vertex of `colour` with its alpha multiplied by `opacity`.
    static LineVertex at(const QVector3D& position, const QColor& colour, float opacity = 1.0f) {
        return {position, QVector4D(colour.redF(), colour.greenF(), colour.blueF(),
                                    colour.alphaF() * opacity)};
    }
};

// Uploaded as a tightly packed array of floats.
static_assert(sizeof(LineVertex) == 7 * sizeof(float));

} // namespace airtrap
