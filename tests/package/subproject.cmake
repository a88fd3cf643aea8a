# ctest: a project that adds gaphys with add_subdirectory (as FetchContent
# does) builds the libraries it links and nothing else: no tests, benchmarks,
# examples, comparison or training workload, and no other engine variant.
# It configures with no Python that has Jinja2 on its PATH, as nothing is
# generated. Only configures and asks Ninja what `all` would build.
# Inputs: SOURCE_DIR (gaphys), WORK_DIR, PYTHON, GENERATOR (Ninja), MAKE_PROGRAM (ninja).
include("${CMAKE_CURRENT_LIST_DIR}/no_jinja2_python.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
file(WRITE "${WORK_DIR}/src/CMakeLists.txt" "cmake_minimum_required(VERSION 3.25)
project(subproject CXX)
add_subdirectory(\"${SOURCE_DIR}\" gaphys)
add_executable(app main.cpp)
target_link_libraries(app PRIVATE gaphys::gaphys)
")
file(WRITE "${WORK_DIR}/src/main.cpp" "#include <gaphys/gaphys.hpp>
int main() { gaphys::world w; w.step(0.01); return 0; }
")
set(no_jinja2 "${WORK_DIR}/no_jinja2")
gaphys_no_jinja2_python("${no_jinja2}" "${PYTHON}")
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PATH=${no_jinja2}:$ENV{PATH}"
                        "${CMAKE_COMMAND}" -S "${WORK_DIR}/src" -B "${WORK_DIR}/build" -G "${GENERATOR}"
                RESULT_VARIABLE failed OUTPUT_QUIET)
if(failed)
  message(FATAL_ERROR "configuring a project that adds gaphys with add_subdirectory failed")
endif()
execute_process(COMMAND "${MAKE_PROGRAM}" -C "${WORK_DIR}/build" -t commands all
                OUTPUT_VARIABLE commands RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "ninja -t commands all failed")
endif()
string(REGEX MATCHALL "-o [^ ]+\\.o" objects "${commands}")
list(LENGTH objects count)
set(unexpected "")
foreach(object IN LISTS objects)
  if(NOT object MATCHES "gaphys/engine/CMakeFiles/gaphys_(engine|scenes)_optimized\\.dir/|CMakeFiles/app\\.dir/")
    list(APPEND unexpected "${object}")
  endif()
endforeach()
if(unexpected OR count EQUAL 0)
  message(FATAL_ERROR "a subproject build compiles more than the libraries it links "
                      "(${count} objects):\n${unexpected}")
endif()
message(STATUS "the subproject compiles ${count} objects: the engine, its scenes and the app")
