#pragma once
// docs/SCENE_FORMAT.md, generated from the parameter declarations so that the document cannot
// drift from what the reader accepts. TestSceneFormatDoc fails when the committed file differs.
#include "scene/Scene.h"

#include <string>

namespace airtrap {

//! The complete Markdown text of docs/SCENE_FORMAT.md.
std::string sceneFormatMarkdown();

//! The example scene shown at the end of the document (valid, without warnings).
Scene sceneFormatExample();

} // namespace airtrap
