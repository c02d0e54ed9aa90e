#include "viewport/GridDrawable.h"

#include <algorithm>
#include <cmath>

namespace airtrap {

namespace {

constexpr float kMinHalfExtent = 2.0f;      // m: even a tiny tank gets a few metres of ground
constexpr float kExtentPerContainer = 1.5f; // half extent per container size
constexpr int kCellsAcross = 20;
constexpr int kMajorEvery = 5;
constexpr int kSegmentsPerLine = 24; // each line is split so that its opacity can fade
const QColor kGridColour(150, 150, 160);
constexpr float kMinorOpacity = 0.22f;
constexpr float kMajorOpacity = 0.45f;

} // namespace

GridDrawable::GridDrawable() {
    lines_.setWidth(1.0f);
}

float GridDrawable::niceCellSize(float span) {
    const float rough = span / float(kCellsAcross);
    const float decade = std::pow(10.0f, std::floor(std::log10(rough)));
    for (const float step : {1.0f, 2.0f, 5.0f}) {
        if (step * decade >= rough) {
            return step * decade;
        }
    }
    return 10.0f * decade;
}

float GridDrawable::fade(float radius, float halfExtent) {
    const float t = std::clamp((radius / halfExtent - 0.4f) / 0.6f, 0.0f, 1.0f);
    return 1.0f - t * t * (3.0f - 2.0f * t);
}

void GridDrawable::fitAround(const Aabb& container) {
    const Vec3d size = container.size();
    const float halfExtent =
        std::max(kMinHalfExtent, kExtentPerContainer * float(std::max(size.x(), size.z())));
    cellSize_ = niceCellSize(2.0f * halfExtent);
    const int halfCells = int(std::ceil(halfExtent / cellSize_));
    // Snap the centre to the lattice, so that lines fall on round world coordinates.
    const float centreX = std::round(float(container.center().x()) / cellSize_) * cellSize_;
    const float centreZ = std::round(float(container.center().z()) / cellSize_) * cellSize_;
    const float floorY = float(container.min.y());
    const float reach = float(halfCells) * cellSize_;

    std::vector<LineVertex> vertices;
    vertices.reserve(std::size_t(2 * (2 * halfCells + 1) * kSegmentsPerLine * 2));
    auto addLine = [&](float offset, bool alongX, float opacity) {
        for (int s = 0; s < kSegmentsPerLine; ++s) {
            for (const int end : {s, s + 1}) {
                const float along = -reach + 2.0f * reach * float(end) / kSegmentsPerLine;
                const float x = alongX ? along : offset;
                const float z = alongX ? offset : along;
                const float radius = std::hypot(x, z);
                vertices.push_back(LineVertex::at(QVector3D(centreX + x, floorY, centreZ + z),
                                                  kGridColour, opacity * fade(radius, reach)));
            }
        }
    };
    for (int i = -halfCells; i <= halfCells; ++i) {
        const int worldIndex = i + int(std::lround(centreX / cellSize_));
        const int worldIndexZ = i + int(std::lround(centreZ / cellSize_));
        const float offset = float(i) * cellSize_;
        addLine(offset, false, worldIndex % kMajorEvery == 0 ? kMajorOpacity : kMinorOpacity);
        addLine(offset, true, worldIndexZ % kMajorEvery == 0 ? kMajorOpacity : kMinorOpacity);
    }
    lines_.setSegments(std::move(vertices));
}

} // namespace airtrap
