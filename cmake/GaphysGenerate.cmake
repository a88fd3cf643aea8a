# gaphys_add_algebra(TARGET <target> SPEC <file.ga>
#                    [VARIANT reference|instrumented|optimized] [NAMESPACE <ns>])
#
# Generates a C++ library from a gaphys spec at build time (again whenever the
# spec or the generator changes) and defines the INTERFACE target <target>:
# link it and `#include <ns/ns.hpp>`. NAMESPACE defaults to the spec's
# algebra name. Usable from gaphys's own build and, after
# find_package(gaphys), from any project.

include_guard(GLOBAL)

# Where the generator lives: set by gaphysConfig.cmake when installed, else the source tree.
if(NOT GAPHYS_GENERATOR_DIR)
  set(GAPHYS_GENERATOR_DIR "${CMAKE_CURRENT_LIST_DIR}/../generator")
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

function(gaphys_add_algebra)
  gaphys_find_generator_python()
  cmake_parse_arguments(ARG "" "TARGET;SPEC;VARIANT;NAMESPACE" "" ${ARGN})
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

  set(out "${CMAKE_CURRENT_BINARY_DIR}/${ARG_TARGET}_generated")
  set(stamp "${out}/${namespace}.stamp")
  file(GLOB generator_sources CONFIGURE_DEPENDS
       "${GAPHYS_GENERATOR_DIR}/gaphys_gen/*.py" "${GAPHYS_GENERATOR_DIR}/gaphys_gen/templates/*.j2")
  add_custom_command(
    OUTPUT "${stamp}"
    COMMAND "${Python3_EXECUTABLE}" "${GAPHYS_GENERATOR_DIR}/gaphys-gen" generate "${spec}"
            --variant ${ARG_VARIANT} --out "${out}" --namespace ${namespace}
    COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}"
    DEPENDS "${spec}" ${generator_sources}
    COMMENT "gaphys: generating ${namespace} (${ARG_VARIANT}) from ${ARG_SPEC}"
    VERBATIM)
  add_custom_target(${ARG_TARGET}_generate DEPENDS "${stamp}")
  add_library(${ARG_TARGET} INTERFACE)
  target_include_directories(${ARG_TARGET} INTERFACE "${out}")
  target_link_libraries(${ARG_TARGET} INTERFACE gaphys::ga_runtime)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_generate)
endfunction()
