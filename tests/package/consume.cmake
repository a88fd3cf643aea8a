# ctest: install gaphys into a scratch prefix, then configure, build and run
# two separate projects against it: examples/consumer (find_package(gaphys) and
# gaphys_add_algebra() on the app's own spec, built in two passes by the
# installed GaphysTwoPass.cmake: its workload's mv calls must get kernels) and
# examples/demo (the engine, gaphys::scenes and gaphys::gaphys, checked through
# the trajectory it writes); and an app whose spec is edited is rebuilt with
# the new algebra by one build (spec_edit.cmake).
# The demo is built without three.js, as a copy outside the gaphys tree would
# be: it must build, and its --html must say how to get three.js.
# Inputs: BUILD_DIR (gaphys's build), SOURCE_DIR, WORK_DIR, PYTHON, GENERATOR, GAPHYS_OTHER_REAL
# (the scalar the package was not built with).
include("${CMAKE_CURRENT_LIST_DIR}/no_jinja2_python.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE failed)
  if(failed)
    string(REPLACE ";" " " shown "${ARGN}")
    message(FATAL_ERROR "failed: ${shown}")
  endif()
endfunction()
run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/install")
include("${CMAKE_CURRENT_LIST_DIR}/two_pass.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/spec_edit.cmake")

# The demo links the engine and generates nothing, so it must configure and
# build with no Python that has Jinja2: the only python3 on its PATH runs
# without site-packages (-S), where Jinja2 lives, and comes first on its PATH.
set(no_jinja2 "${WORK_DIR}/no_jinja2")
gaphys_no_jinja2_python("${no_jinja2}" "${PYTHON}")
run("${CMAKE_COMMAND}" -E env "PATH=${no_jinja2}:$ENV{PATH}"
    "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/examples/demo" -B "${WORK_DIR}/demo" -G "${GENERATOR}"
    "-DCMAKE_PREFIX_PATH=${WORK_DIR}/install" "-DGAPHYS_DEMO_THREE_JS=")
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/demo")
# 10 spheres recorded at steps 0, 30 and 60: a header and 30 rows.
set(demo "${WORK_DIR}/demo/gaphys_demo" --scene falling_spheres --spheres 10 --steps 60 --every 30)
run(${demo} --out "${WORK_DIR}/trajectory.csv")
file(STRINGS "${WORK_DIR}/trajectory.csv" lines)
list(POP_FRONT lines header)
list(LENGTH lines rows)
if(NOT header STREQUAL "time,body,x,y,z,r_scalar,r_e12,r_e13,r_e23" OR NOT rows EQUAL 30)
  message(FATAL_ERROR "trajectory.csv: header '${header}' and ${rows} rows; expected "
                      "'time,body,x,y,z,r_scalar,r_e12,r_e13,r_e23' and 30 rows")
endif()
# The same run as JSON: 3 frames of 10 bodies.
run(${demo} --out "${WORK_DIR}/trajectory.json")
file(READ "${WORK_DIR}/trajectory.json" json)
string(SUBSTRING "${json}" 0 1 first)
string(JSON frames ERROR_VARIABLE bad LENGTH "${json}" frames)
if(NOT bad)
  string(JSON bodies ERROR_VARIABLE bad LENGTH "${json}" frames 2 bodies)
endif()
if(NOT first STREQUAL "{" OR bad OR NOT frames EQUAL 3 OR NOT bodies EQUAL 10)
  message(FATAL_ERROR "trajectory.json: expected an object of 3 frames of 10 bodies; got "
                      "'${first}...', ${frames} frames, ${bodies} bodies in the last (${bad})")
endif()
# --html without three.js: exit code 1, the way out, and no file made.
execute_process(COMMAND ${demo} --html "${WORK_DIR}/page.html" RESULT_VARIABLE code
                ERROR_VARIABLE errors OUTPUT_QUIET)
if(NOT code EQUAL 1 OR NOT errors MATCHES "built without three.js: run npm ci"
   OR EXISTS "${WORK_DIR}/page.html")
  message(FATAL_ERROR "gaphys_demo --html built without three.js: exit code ${code}, expected 1 "
                      "and 'built without three.js: run npm ci', and no page:\n${errors}")
endif()
file(GLOB temporaries "${WORK_DIR}/*.tmp.*")
if(temporaries)
  message(FATAL_ERROR "the demo left temporary files: ${temporaries}")
endif()

# An app asking for the other scalar than the package's does not find it, and
# is told why (it was given a double engine unasked).
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PATH=${no_jinja2}:$ENV{PATH}"
                "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/examples/demo" -B "${WORK_DIR}/demo_other_real"
                -G "${GENERATOR}" "-DCMAKE_PREFIX_PATH=${WORK_DIR}/install"
                "-DGAPHYS_DEMO_THREE_JS=" "-DGAPHYS_REAL=${GAPHYS_OTHER_REAL}"
                RESULT_VARIABLE code OUTPUT_VARIABLE output ERROR_VARIABLE errors)
string(REGEX REPLACE "[ \n]+" " " said "${output}${errors}")  # as CMake wraps it
if(code EQUAL 0 OR NOT said MATCHES
   "was built with GAPHYS_REAL=[a-z]+, and GAPHYS_REAL is ${GAPHYS_OTHER_REAL} here")
  message(FATAL_ERROR "the demo configured with GAPHYS_REAL=${GAPHYS_OTHER_REAL} against the "
                      "package: exit code ${code}, expected a failure naming both scalars:\n"
                      "${output}${errors}")
endif()
