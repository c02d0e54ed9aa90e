# The Blender tests' input: a short bake of the pouring sample, its post results and an export of
# every format, Z up as Blender is and Y up; and three frames of the buoyancy sample, for its
# bodies.
#   cmake -DCLI=<airtrap-cli> -DSAMPLES=<samples folder> -DOUT=<folder> -P MakeExport.cmake
cmake_minimum_required(VERSION 3.25)
# Only its own folders: the other Blender tests write beside them.
file(REMOVE_RECURSE ${OUT}/cache ${OUT}/export ${OUT}/export-y-up ${OUT}/bodies-cache
     ${OUT}/bodies-export)
function(run)
    execute_process(COMMAND ${CLI} ${ARGN} -q RESULT_VARIABLE result ERROR_VARIABLE errors)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "airtrap-cli ${ARGN} exited ${result}: ${errors}")
    endif()
endfunction()
run(bake ${SAMPLES}/pouring.json --out ${OUT}/cache --set frames.end_frame=15)
run(post ${OUT}/cache)
foreach(format obj ply vdb)
    run(export ${OUT}/cache --format ${format} --out ${OUT}/export --up z)
    run(export ${OUT}/cache --format ${format} --out ${OUT}/export-y-up --up y)
endforeach()
run(bake ${SAMPLES}/buoyancy.json --out ${OUT}/bodies-cache --set frames.end_frame=3)
run(post ${OUT}/bodies-cache)
run(export ${OUT}/bodies-cache --format obj --out ${OUT}/bodies-export --up z)
message(STATUS "exported ${OUT}/export, ${OUT}/export-y-up and ${OUT}/bodies-export")
