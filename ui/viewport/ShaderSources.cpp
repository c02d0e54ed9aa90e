#include "viewport/ShaderSources.h"

#include <QDebug>

namespace airtrap {

std::unique_ptr<QOpenGLShaderProgram> ShaderSources::build() const {
    auto program = std::make_unique<QOpenGLShaderProgram>();
    bool ok = program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex);
    if (ok && !geometry.isEmpty()) {
        ok = program->addShaderFromSourceCode(QOpenGLShader::Geometry, geometry);
    }
    ok = ok && program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment);
    ok = ok && program->link();
    if (!ok) {
        qWarning().noquote() << "Viewport shader" << name << "failed:" << program->log();
        return nullptr;
    }
    return program;
}

} // namespace airtrap
