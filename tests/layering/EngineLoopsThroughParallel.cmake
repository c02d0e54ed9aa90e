# The engine's parallel loops go through engine/core/Parallel.h (docs/ARCHITECTURE.md "The
# step"), whose fork/join annotations let the thread sanitizer build see each loop's order
# (docs/TESTING.md "Sanitizers"). A tbb:: algorithm called anywhere else in engine/ fails this
# check: that loop would be invisible to TSan and reported as a race.
#   cmake -DENGINE_DIR=<source>/engine -P EngineLoopsThroughParallel.cmake
cmake_minimum_required(VERSION 3.25)
file(GLOB_RECURSE files ${ENGINE_DIR}/*.h ${ENGINE_DIR}/*.cpp)
set(checked 0)
set(violations "")
foreach(file IN LISTS files)
    if(file MATCHES "/engine/core/Parallel.h$")
        continue()
    endif()
    math(EXPR checked "${checked} + 1")
    file(STRINGS ${file} calls REGEX "tbb::parallel_[a-z_]+|tbb::task_group")
    foreach(line IN LISTS calls)
        string(STRIP "${line}" line)
        list(APPEND violations "${file}: ${line}")
    endforeach()
endforeach()
if(checked EQUAL 0)
    message(FATAL_ERROR "no engine files found under '${ENGINE_DIR}'")
endif()
if(violations)
    list(JOIN violations "\n  " listed)
    message(FATAL_ERROR "tbb:: algorithms called outside core/Parallel.h:\n  ${listed}")
endif()
message(STATUS "${checked} engine files start their parallel loops through core/Parallel.h")
