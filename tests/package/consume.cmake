# ctest: install gaphys into a scratch prefix, then configure, build and run
# examples/consumer against it as a separate project (find_package(gaphys) and
# gaphys_add_algebra() on the app's own spec).
# Inputs: BUILD_DIR (gaphys's build), SOURCE_DIR, WORK_DIR, PYTHON, GENERATOR.
file(REMOVE_RECURSE "${WORK_DIR}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE failed)
  if(failed)
    string(REPLACE ";" " " shown "${ARGN}")
    message(FATAL_ERROR "failed: ${shown}")
  endif()
endfunction()
run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/install")
run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/examples/consumer" -B "${WORK_DIR}/build" -G "${GENERATOR}"
    "-DCMAKE_PREFIX_PATH=${WORK_DIR}/install" "-DPython3_EXECUTABLE=${PYTHON}")
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/build")
run("${WORK_DIR}/build/consumer_app")
