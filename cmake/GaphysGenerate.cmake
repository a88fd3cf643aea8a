# gaphys_add_algebra(TARGET <target> SPEC <file.ga>
#                    [VARIANT reference|instrumented|optimized] [NAMESPACE <ns>]
#                    [PROFILE <profile.json> [COVERAGE <c>]])
#
# Generates a C++ library from a gaphys spec at build time (again whenever the
# spec, the profile or the generator changes) and defines the INTERFACE target
# <target>: link it and `#include <ns/ns.hpp>`. NAMESPACE defaults to the
# spec's algebra name. PROFILE (optimized only) is a profile of this spec, as
# the instrumented variant records it: the (function, argument bitmaps)
# combinations on `mv` covering COVERAGE (default 0.999) of its calls get
# straight-line kernels. Usable from gaphys's own build and, after
# find_package(gaphys), from any project.
#
# The two-pass build (GaphysTwoPass.cmake, installed beside this file) sets
#   GAPHYS_TWO_PASS=instrument: every algebra declared VARIANT optimized is
#     generated instrumented instead, and its spec is noted in
#     <build>/gaphys-two-pass/algebras/<ns>.cmake for the merge;
#   GAPHYS_TWO_PASS=optimize with GAPHYS_TWO_PASS_PROFILES=<folder> (and
#     GAPHYS_TWO_PASS_COVERAGE): every algebra declared VARIANT optimized
#     without a PROFILE of its own takes <folder>/<ns>.json, when the run
#     recorded one.
# Unset, nothing changes.

include_guard(GLOBAL)

# Where the generator lives: set by gaphysConfig.cmake when installed, else the source tree.
if(NOT GAPHYS_GENERATOR_DIR)
  set(GAPHYS_GENERATOR_DIR "${CMAKE_CURRENT_LIST_DIR}/../generator")
endif()

# The two-pass settings are checked once, when this file is included.
if(GAPHYS_TWO_PASS AND NOT GAPHYS_TWO_PASS MATCHES "^(instrument|optimize)$")
  message(FATAL_ERROR "GAPHYS_TWO_PASS must be instrument, optimize or empty, not '${GAPHYS_TWO_PASS}'")
endif()
if(GAPHYS_TWO_PASS STREQUAL "optimize" AND NOT IS_DIRECTORY "${GAPHYS_TWO_PASS_PROFILES}")
  message(FATAL_ERROR "GAPHYS_TWO_PASS=optimize needs GAPHYS_TWO_PASS_PROFILES, the folder of the merged "
                      "profiles, not '${GAPHYS_TWO_PASS_PROFILES}'")
endif()
if(GAPHYS_TWO_PASS STREQUAL "optimize" AND NOT GAPHYS_TWO_PASS_COVERAGE)
  set(GAPHYS_TWO_PASS_COVERAGE 0.999)
endif()

# gaphys_find_generator_python(): a Python 3 that can import jinja2, in
# Python3_EXECUTABLE of the caller's scope, or a configure error saying how
# to get one. Only generating needs it: gaphys_add_algebra calls it, so an
# app that links the installed engine or algebras needs no Python at all.
macro(gaphys_find_generator_python)
  find_package(Python3 COMPONENTS Interpreter REQUIRED)
  execute_process(COMMAND "${Python3_EXECUTABLE}" -c "import jinja2"
                  RESULT_VARIABLE _gaphys_no_jinja2 OUTPUT_QUIET ERROR_QUIET)
  if(_gaphys_no_jinja2)
    message(FATAL_ERROR "gaphys: ${Python3_EXECUTABLE} cannot import jinja2. Install Debian's "
                        "python3-jinja2 and pass -DPython3_EXECUTABLE=/usr/bin/python3, or use a "
                        "Python that has Jinja2.")
  endif()
endmacro()

# _gaphys_check_profile(<caller> <variant> <profile> <coverage> <out_profile> <out_coverage>):
# the profile's absolute path and the coverage (0.999 when empty), or a
# configure error naming what is wrong. An empty profile stays empty.
function(_gaphys_check_profile caller variant profile coverage out_profile out_coverage)
  if(NOT profile)
    if(NOT coverage STREQUAL "")
      message(FATAL_ERROR "${caller}: COVERAGE ${coverage} needs a PROFILE")
    endif()
    set(${out_profile} "" PARENT_SCOPE)
    set(${out_coverage} "" PARENT_SCOPE)
    return()
  endif()
  if(NOT variant STREQUAL "optimized")
    message(FATAL_ERROR "${caller}: PROFILE goes with VARIANT optimized, not ${variant} "
                        "(the profile chooses the optimized variant's mv kernels)")
  endif()
  get_filename_component(profile "${profile}" ABSOLUTE)
  if(IS_DIRECTORY "${profile}")
    message(FATAL_ERROR "${caller}: profile '${profile}' is a folder, not a profile file (the "
                        "instrumented variant writes <folder>/<namespace>.json)")
  endif()
  if(NOT EXISTS "${profile}")
    message(FATAL_ERROR "${caller}: profile '${profile}' not found (record one by running the "
                        "instrumented variant with GAPHYS_PROFILE_DIR set)")
  endif()
  if(coverage STREQUAL "")
    set(coverage 0.999)
  endif()
  if(NOT coverage MATCHES "^(0?\\.[0-9]+|[01](\\.[0-9]*)?)$" OR coverage EQUAL 0 OR coverage GREATER 1)
    message(FATAL_ERROR "${caller}: COVERAGE must be a share of calls in (0, 1], not '${coverage}'")
  endif()
  set(${out_profile} "${profile}" PARENT_SCOPE)
  set(${out_coverage} "${coverage}" PARENT_SCOPE)
endfunction()

# _gaphys_generate_target(<name> <spec> <variant> <namespace> <out> <profile> <coverage>):
# the custom target <name> that writes <out>/<namespace>/ from <spec> (and
# <profile>, if not empty) and rewrites it whenever they or the generator change.
function(_gaphys_generate_target name spec variant namespace out profile coverage)
  set(stamp "${out}/${namespace}.stamp")
  set(profile_arguments "")
  set(described "${namespace} (${variant})")
  if(profile)
    set(profile_arguments --profile "${profile}" --coverage ${coverage})
    set(described "${namespace} (${variant}, profile ${profile}, coverage ${coverage})")
  endif()
  file(GLOB generator_sources CONFIGURE_DEPENDS
       "${GAPHYS_GENERATOR_DIR}/gaphys_gen/*.py" "${GAPHYS_GENERATOR_DIR}/gaphys_gen/templates/*.j2")
  # The headers it writes (the same eight for every spec and variant:
  # render.files_for; test_render.py checks this list against it), named so
  # that Ninja looks at their times again after the command has run. It
  # reads a compilation's headers before, and with only the stamp known, a
  # changed spec rebuilt the app one build late. (The generator leaves
  # unchanged headers untouched, so only what includes a changed one is
  # compiled again.)
  set(headers "")
  foreach(header IN ITEMS ${namespace} tables types mv_functions kernels recording specialized batch)
    list(APPEND headers "${out}/${namespace}/${header}.hpp")
  endforeach()
  add_custom_command(
    OUTPUT "${stamp}"
    BYPRODUCTS ${headers}
    COMMAND "${Python3_EXECUTABLE}" "${GAPHYS_GENERATOR_DIR}/gaphys-gen" generate "${spec}"
            --variant ${variant} --out "${out}" --namespace ${namespace} ${profile_arguments}
    COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}"
    DEPENDS "${spec}" ${profile} ${generator_sources}
    COMMENT "gaphys: generating ${described} from ${spec}"
    VERBATIM)
  add_custom_target(${name} DEPENDS "${stamp}")
endfunction()

function(gaphys_add_algebra)
  gaphys_find_generator_python()
  cmake_parse_arguments(ARG "" "TARGET;SPEC;VARIANT;NAMESPACE;PROFILE;COVERAGE" "" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "gaphys_add_algebra: unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_TARGET OR NOT ARG_SPEC)
    message(FATAL_ERROR "gaphys_add_algebra: TARGET and SPEC are required")
  endif()
  if(NOT ARG_VARIANT)
    set(ARG_VARIANT optimized)
  endif()
  if(NOT ARG_VARIANT MATCHES "^(reference|instrumented|optimized)$")
    message(FATAL_ERROR "gaphys_add_algebra: VARIANT must be reference, instrumented or optimized, "
                        "not '${ARG_VARIANT}'")
  endif()
  get_filename_component(spec "${ARG_SPEC}" ABSOLUTE)
  if(NOT EXISTS "${spec}")
    message(FATAL_ERROR "gaphys_add_algebra: spec '${spec}' not found")
  endif()
  set(namespace "${ARG_NAMESPACE}")
  if(NOT namespace)
    file(STRINGS "${spec}" algebra_line REGEX "^[ \t]*algebra[ \t]+[A-Za-z_][A-Za-z_0-9]*")
    string(REGEX REPLACE "^[ \t]*algebra[ \t]+([A-Za-z_][A-Za-z_0-9]*).*" "\\1" namespace "${algebra_line}")
  endif()
  _gaphys_check_profile("gaphys_add_algebra(${ARG_TARGET})" ${ARG_VARIANT} "${ARG_PROFILE}" "${ARG_COVERAGE}"
                        profile coverage)

  # The two-pass build (see the top of this file) overrides VARIANT optimized.
  set(variant ${ARG_VARIANT})
  if(variant STREQUAL "optimized" AND GAPHYS_TWO_PASS STREQUAL "instrument")
    set(variant instrumented)
    set(profile "")
    file(WRITE "${CMAKE_BINARY_DIR}/gaphys-two-pass/algebras/${namespace}.cmake"
         "set(gaphys_spec [==[${spec}]==])\n"
         "set(gaphys_generator [==[${GAPHYS_GENERATOR_DIR}/gaphys-gen]==])\n")
  elseif(variant STREQUAL "optimized" AND GAPHYS_TWO_PASS STREQUAL "optimize" AND NOT profile)
    if(EXISTS "${GAPHYS_TWO_PASS_PROFILES}/${namespace}.json")
      _gaphys_check_profile("gaphys_add_algebra(${ARG_TARGET})" optimized
                            "${GAPHYS_TWO_PASS_PROFILES}/${namespace}.json" "${GAPHYS_TWO_PASS_COVERAGE}"
                            profile coverage)
    else()
      message(STATUS "gaphys: the profiling run recorded no calls of ${namespace}; "
                     "${ARG_TARGET} is generated without a profile")
    endif()
  endif()

  set(out "${CMAKE_CURRENT_BINARY_DIR}/${ARG_TARGET}_generated")
  _gaphys_generate_target(${ARG_TARGET}_generate "${spec}" ${variant} ${namespace} "${out}" "${profile}"
                          "${coverage}")
  add_library(${ARG_TARGET} INTERFACE)
  target_include_directories(${ARG_TARGET} INTERFACE "${out}")
  target_link_libraries(${ARG_TARGET} INTERFACE gaphys::ga_runtime)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_generate)
endfunction()
