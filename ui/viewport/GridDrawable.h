#pragma once
// The ground grid: square cells on the container's floor plane, reaching a few metres beyond the
// container and fading out towards its edge so that it has no hard border. Every fifth line is
// brighter; the cell size is 1, 2 or 5 times a power of ten, picked so that ~20 cells span it.
#include "core/Math.h"
#include "viewport/Drawable.h"
#include "viewport/LineBatch.h"

namespace airtrap {

class GridDrawable : public Drawable {
public:
    GridDrawable();

    //! Lays the grid on the floor of `container`, centred under it.
    void fitAround(const Aabb& container);
    //! Metres between neighbouring lines of the current grid.
    float cellSize() const { return cellSize_; }

    //! Builds the line shader.
    void initialize() override { lines_.initialize(); }
    //! Draws the grid, depth-tested.
    void draw(const RenderContext& context) override { lines_.draw(context); }
    //! Frees the GL objects.
    void release() override { lines_.release(); }

private:
    static float niceCellSize(float span);
    //! Opacity at `radius` metres from the centre, for a grid reaching `halfExtent`.
    static float fade(float radius, float halfExtent);

    LineBatch lines_;
    float cellSize_ = 1.0f;
};

} // namespace airtrap
