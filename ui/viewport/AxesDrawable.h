#pragma once
// The world axes at the origin: x red, y green, z blue, as in most 3D tools.
#include "viewport/Drawable.h"
#include "viewport/LineBatch.h"

namespace airtrap {

class AxesDrawable : public Drawable {
public:
    AxesDrawable();

    //! Sets how far each axis reaches from the origin, in metres.
    void setLength(float metres);

    //! Builds the line shader.
    void initialize() override { lines_.initialize(); }
    //! Draws the three axes, depth-tested.
    void draw(const RenderContext& context) override { lines_.draw(context); }
    //! Frees the GL objects.
    void release() override { lines_.release(); }

private:
    LineBatch lines_;
};

} // namespace airtrap
