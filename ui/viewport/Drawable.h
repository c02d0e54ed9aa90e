#pragma once
// One kind of thing the viewport draws. Its data may change at any time (setters only store it);
// GL work happens in initialize(), draw() and release(), always with the viewport's context
// current, because the context may not exist yet when the data arrives.
namespace airtrap {

struct RenderContext;

class Drawable {
public:
    virtual ~Drawable() = default;

    //! Creates shaders and buffers in a fresh context. Everything uploaded before is gone, so the
    //! drawable uploads its data again on the next draw().
    virtual void initialize() = 0;
    //! Uploads what changed since the last draw, then draws.
    virtual void draw(const RenderContext& context) = 0;
    //! Frees the GL objects while their context is still current.
    virtual void release() = 0;
};

} // namespace airtrap
