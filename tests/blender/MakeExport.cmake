# The Blender tests' input: a short bake of the pouring sample, its post results and an export of
# every format, Z up as Blender is.
#   cmake -DCLI=<airtrap-cli> -DSCENE=<pouring.json> -DOUT=<folder> -P MakeExport.cmake
cmake_minimum_required(VERSION 3.25)
# Only its own folders: the other Blender tests write beside them.
file(REMOVE_RECURSE ${OUT}/cache ${OUT}/export)
function(run)
    execute_process(COMMAND ${CLI} ${ARGN} -q RESULT_VARIABLE result ERROR_VARIABLE errors)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "airtrap-cli ${ARGN} exited ${result}: ${errors}")
    endif()
endfunction()
run(bake ${SCENE} --out ${OUT}/cache --set frames.end_frame=15)
run(post ${OUT}/cache)
foreach(format obj ply vdb)
    run(export ${OUT}/cache --format ${format} --out ${OUT}/export --up z)
endforeach()
message(STATUS "exported ${OUT}/export")
