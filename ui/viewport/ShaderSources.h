#pragma once
// The GLSL 330 core sources of one shader program, kept as string constants next to the drawable
// that uses them: no resource files to load, so a static library and its tests just work.
#include <QOpenGLShaderProgram>
#include <QString>
#include <memory>

namespace airtrap {

struct ShaderSources {
    const char* name = ""; //!< for messages
    QString vertex;        //!< required
    QString geometry;      //!< optional: empty for none
    QString fragment;      //!< required

    //! Compiles and links the program in the current context; on failure logs the compiler's
    //! message with `name` and returns null, and the drawable then draws nothing.
    std::unique_ptr<QOpenGLShaderProgram> build() const;
};

} // namespace airtrap
