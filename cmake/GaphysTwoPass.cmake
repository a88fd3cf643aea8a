# The two-pass profile-guided build of an app that uses gaphys: profile the
# app's own workload, then build it with the algebras specialized for it.
#
#   cmake -D BUILD_DIR=build [-D SOURCE_DIR=.] [-D COVERAGE=0.999]
#         [-D "CONFIGURE_ARGS=-G Ninja -DCMAKE_PREFIX_PATH=<gaphys prefix>"]
#         [-D BUILD_TARGET=<what to build>] [-D PYTHON=<python3 with jinja2>]
#         [-D GAPHYS_SOURCE_DIR=<gaphys checkout>]
#         -P <gaphys prefix>/lib/cmake/gaphys/GaphysTwoPass.cmake -- ./my_app --my-args
#
# 1. Configures and builds the app in BUILD_DIR/gaphys-two-pass/instrumented
#    with GAPHYS_TWO_PASS=instrument: every algebra it declares with
#    gaphys_add_algebra(... VARIANT optimized) is generated instrumented.
# 2. Runs the command after `--` there (so ./my_app is the instrumented app)
#    with GAPHYS_PROFILE_DIR=BUILD_DIR/gaphys-two-pass/recorded.
# 3. Merges each recorded profile (gaphys-gen merge, which checks it against
#    the spec) into BUILD_DIR/gaphys-two-pass/profiles/<ns>.json and prints
#    its report (gaphys-gen report) at COVERAGE.
# 4. Configures and builds the app in BUILD_DIR with GAPHYS_TWO_PASS=optimize:
#    those algebras are generated optimized with PROFILE <ns>.json.
#
# With GAPHYS_SOURCE_DIR, the engine is profiled too: gaphys is built and
# installed instrumented (GAPHYS_ALGEBRA_VARIANT=instrumented) for the first
# pass, and optimized from the recorded e3ga.json and c3ga.json
# (GAPHYS_ENGINE_PROFILE_DIR) for the second, under BUILD_DIR/gaphys-two-pass/.
# Running this again reuses the build trees: only what changed is rebuilt.

cmake_minimum_required(VERSION 3.25)

if(NOT BUILD_DIR)
  message(FATAL_ERROR "GaphysTwoPass: set BUILD_DIR (cmake -D BUILD_DIR=build ... -P GaphysTwoPass.cmake -- "
                      "<command that runs the app>)")
endif()
if(NOT SOURCE_DIR)
  set(SOURCE_DIR .)
endif()
if(NOT COVERAGE)
  set(COVERAGE 0.999)
endif()
# CONFIGURE_ARGS is one string, split as a shell would: quote what has spaces.
separate_arguments(CONFIGURE_ARGS UNIX_COMMAND "${CONFIGURE_ARGS}")
get_filename_component(SOURCE_DIR "${SOURCE_DIR}" ABSOLUTE)
get_filename_component(BUILD_DIR "${BUILD_DIR}" ABSOLUTE)

# The command: every argument after `--`.
set(command "")
set(after_dashes OFF)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE 1 ${last})
  if(after_dashes)
    list(APPEND command "${CMAKE_ARGV${i}}")
  elseif(CMAKE_ARGV${i} STREQUAL "--")
    set(after_dashes ON)
  endif()
endforeach()
if(NOT command)
  message(FATAL_ERROR "GaphysTwoPass: give the command that runs the app's workload after `--`, "
                      "e.g. -P GaphysTwoPass.cmake -- ./my_app --scene big")
endif()

set(work "${BUILD_DIR}/gaphys-two-pass")
set(instrumented "${work}/instrumented")
set(recorded "${work}/recorded")
set(profiles "${work}/profiles")

function(run what)
  string(REPLACE ";" " " shown "${ARGN}")
  message(STATUS "gaphys two-pass: ${what}: ${shown}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "gaphys two-pass: ${what} failed (${failed}): ${shown}")
  endif()
endfunction()

# gaphys itself, built and installed with the given options into <prefix>;
# sets gaphys_dir to its package folder.
function(build_gaphys name)
  set(build "${work}/gaphys-${name}-build")
  set(prefix "${work}/gaphys-${name}")
  set(python_argument "")
  if(PYTHON)
    set(python_argument "-DPython3_EXECUTABLE=${PYTHON}")
  endif()
  run("configure gaphys (${name})" "${CMAKE_COMMAND}" -S "${GAPHYS_SOURCE_DIR}" -B "${build}" ${CONFIGURE_ARGS}
      ${python_argument} -DGAPHYS_BUILD_TESTS=OFF -DGAPHYS_BUILD_BENCHMARKS=OFF -DGAPHYS_BUILD_EXAMPLES=OFF
      -DGAPHYS_BUILD_COMPARE=OFF -DCMAKE_INSTALL_LIBDIR=lib ${ARGN})
  run("build gaphys (${name})" "${CMAKE_COMMAND}" --build "${build}")
  run("install gaphys (${name})" "${CMAKE_COMMAND}" --install "${build}" --prefix "${prefix}")
  set(gaphys_dir "${prefix}/lib/cmake/gaphys" PARENT_SCOPE)
endfunction()

set(build_target "")
if(BUILD_TARGET)
  set(build_target --target ${BUILD_TARGET})
endif()

# ---- pass 1: instrumented --------------------------------------------------
set(package_argument "")
if(GAPHYS_SOURCE_DIR)
  get_filename_component(GAPHYS_SOURCE_DIR "${GAPHYS_SOURCE_DIR}" ABSOLUTE)
  build_gaphys(instrumented -DGAPHYS_ALGEBRA_VARIANT=instrumented -DGAPHYS_ENGINE_PROFILE_DIR=)
  set(package_argument "-Dgaphys_DIR=${gaphys_dir}")
endif()
file(REMOVE_RECURSE "${instrumented}/gaphys-two-pass/algebras")
run("configure (instrumented)" "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${instrumented}" ${CONFIGURE_ARGS}
    ${package_argument} -DGAPHYS_TWO_PASS=instrument)
run("build (instrumented)" "${CMAKE_COMMAND}" --build "${instrumented}" ${build_target})

file(GLOB algebras "${instrumented}/gaphys-two-pass/algebras/*.cmake")
if(NOT algebras)
  message(FATAL_ERROR "gaphys two-pass: nothing to profile: the app declares no gaphys_add_algebra(... "
                      "VARIANT optimized) and links no instrumented engine (set GAPHYS_SOURCE_DIR)")
endif()

file(REMOVE_RECURSE "${recorded}" "${profiles}")
file(MAKE_DIRECTORY "${recorded}" "${profiles}")
set(ENV{GAPHYS_PROFILE_DIR} "${recorded}")
string(REPLACE ";" " " shown "${command}")
message(STATUS "gaphys two-pass: run (instrumented, in ${instrumented}): ${shown}")
execute_process(COMMAND ${command} WORKING_DIRECTORY "${instrumented}" RESULT_VARIABLE failed)
unset(ENV{GAPHYS_PROFILE_DIR})
if(failed)
  message(FATAL_ERROR "gaphys two-pass: the command failed (${failed}): ${shown}")
endif()

# ---- merge -----------------------------------------------------------------
if(NOT PYTHON)
  # The Python the app's configure used: Python3_EXECUTABLE where the user
  # gave one, else the one find_package(Python3) found (which it caches as
  # _Python3_EXECUTABLE); else one on the PATH.
  foreach(entry IN ITEMS Python3_EXECUTABLE _Python3_EXECUTABLE)
    file(STRINGS "${instrumented}/CMakeCache.txt" cached REGEX "^${entry}:")
    string(REGEX REPLACE "^[^=]*=" "" PYTHON "${cached}")
    if(PYTHON)
      break()
    endif()
  endforeach()
  if(NOT PYTHON)
    unset(PYTHON)  # (an empty PYTHON would hide the one find_program caches)
    find_program(PYTHON NAMES python3 REQUIRED)
  endif()
endif()
set(merged "")
foreach(algebra IN LISTS algebras)
  get_filename_component(namespace "${algebra}" NAME_WE)
  include("${algebra}")
  if(NOT EXISTS "${recorded}/${namespace}.json")
    message(STATUS "gaphys two-pass: the run made no calls of ${namespace}")
    continue()
  endif()
  run("merge ${namespace}" "${PYTHON}" "${gaphys_generator}" merge --spec "${gaphys_spec}"
      --out "${profiles}/${namespace}.json" "${recorded}/${namespace}.json")
  run("report ${namespace}" "${PYTHON}" "${gaphys_generator}" report "${profiles}/${namespace}.json"
      --spec "${gaphys_spec}" --coverage ${COVERAGE} --top 10)
  list(APPEND merged ${namespace})
endforeach()
if(NOT merged)
  message(FATAL_ERROR "gaphys two-pass: the command recorded no profile in ${recorded}: does it run the "
                      "app built in ${instrumented}?")
endif()

# ---- pass 2: optimized with the profiles --------------------------------------
set(package_argument "")
if(GAPHYS_SOURCE_DIR)
  build_gaphys(optimized -DGAPHYS_ALGEBRA_VARIANT=optimized "-DGAPHYS_ENGINE_PROFILE_DIR=${profiles}"
               -DGAPHYS_ENGINE_PROFILE_COVERAGE=${COVERAGE})
  set(package_argument "-Dgaphys_DIR=${gaphys_dir}")
endif()
run("configure (optimized)" "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${BUILD_DIR}" ${CONFIGURE_ARGS}
    ${package_argument} -DGAPHYS_TWO_PASS=optimize "-DGAPHYS_TWO_PASS_PROFILES=${profiles}"
    -DGAPHYS_TWO_PASS_COVERAGE=${COVERAGE})
run("build (optimized)" "${CMAKE_COMMAND}" --build "${BUILD_DIR}" ${build_target})
string(REPLACE ";" ", " merged "${merged}")
message(STATUS "gaphys two-pass: ${BUILD_DIR} is built with the profiles of ${merged} (${profiles})")
