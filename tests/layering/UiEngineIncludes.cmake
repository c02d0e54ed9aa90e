# The editor's rule (docs/ARCHITECTURE.md "The editor's threads"): only ui/controller runs the
# engine's operations (baking, reading caches and meshes, validating, post, export). The other
# folders of ui/ may include the engine's value types and the pure helpers that compute geometry
# or text from them, listed here. A new engine include outside ui/controller fails this check
# until it goes through a controller or joins the list for a reason.
#   cmake -DUI_DIR=<source>/ui -P UiEngineIncludes.cmake
cmake_minimum_required(VERSION 3.25)
set(allowed
    bake/BakeProgress.h
    bubbles/BubbleState.h
    cache/FrameFile.h
    core/Error.h
    core/Math.h
    core/UpAxis.h
    post/OscillatingBubbleMesh.h
    post/SubgridBubble.h
    rigid/EulerRotation.h
    rigid/RigidBodyState.h
    rigid/TriangleMesh.h
    scene/InflowNozzle.h
    scene/ParameterCodec.h
    scene/ParameterDeclaration.h
    scene/Scene.h
    scene/SceneJson.h
    scene/SceneSchema.h
    sim/FrameStats.h
    sim/SimulationState.h)
set(layers "core|scene|rigid|sph|bubbles|sim|cache|bake|post|io")

file(GLOB_RECURSE files ${UI_DIR}/*.h ${UI_DIR}/*.cpp)
set(checked 0)
set(violations "")
foreach(file IN LISTS files)
    if(file MATCHES "/ui/controller/")
        continue()
    endif()
    math(EXPR checked "${checked} + 1")
    file(STRINGS ${file} includes REGEX "^#include \"(${layers})/")
    foreach(line IN LISTS includes)
        string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" header "${line}")
        if(NOT header IN_LIST allowed)
            list(APPEND violations "${file}: ${header}")
        endif()
    endforeach()
endforeach()
if(checked EQUAL 0)
    message(FATAL_ERROR "no ui files found under '${UI_DIR}'")
endif()
if(violations)
    list(JOIN violations "\n  " listed)
    message(FATAL_ERROR "engine operations reached from outside ui/controller:\n  ${listed}")
endif()
message(STATUS "${checked} ui files outside ui/controller include only engine value types")
