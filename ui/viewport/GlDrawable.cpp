#include "viewport/GlDrawable.h"

namespace airtrap {

void GlDrawable::ownBuffer(QOpenGLBuffer& buffer, QOpenGLBuffer::UsagePattern usage) {
    buffers_.push_back({&buffer, usage});
}

void GlDrawable::initialize() {
    program_ = shaderSources().build();
    vertexArray_.create();
    for (const OwnedBuffer& owned : buffers_) {
        owned.buffer->create();
        owned.buffer->setUsagePattern(owned.usage);
    }
    setUpBuffers();
    // Whatever a lost context held is gone: upload again.
    changed_ = true;
}

void GlDrawable::draw(const RenderContext& context) {
    if (!program_)
        return;
    if (changed_) {
        changed_ = false;
        upload();
    }
    if (!hasUploaded())
        return;
    program_->bind();
    render(context, *program_);
    program_->release();
}

void GlDrawable::release() {
    program_.reset();
    releaseUploads();
    for (const OwnedBuffer& owned : buffers_)
        owned.buffer->destroy();
    vertexArray_.destroy();
}

} // namespace airtrap
