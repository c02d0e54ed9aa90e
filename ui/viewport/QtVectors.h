// Conversions from engine vectors and Qt colours to the QVector3D the shaders take.
#pragma once

#include "core/Math.h"

#include <QColor>
#include <QVector3D>

namespace airtrap {

inline QVector3D toQVector3D(const Vec3d& v) {
    return QVector3D(float(v.x()), float(v.y()), float(v.z()));
}

inline Vec3d toVec3d(const QVector3D& v) {
    return Vec3d(v.x(), v.y(), v.z());
}

inline QVector3D rgbVector(const QColor& colour) {
    return QVector3D(float(colour.redF()), float(colour.greenF()), float(colour.blueF()));
}

} // namespace airtrap
