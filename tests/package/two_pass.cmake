# Part of consume.cmake (its run(), WORK_DIR, SOURCE_DIR, PYTHON, GENERATOR):
# examples/consumer built in two passes by the installed GaphysTwoPass.cmake,
# with its own workload (./consumer_app) as the profiling run. Then:
# - the optimized e2ga carries the merged profile, and mv kernels for the
#   workload's undeclared combinations (rotor * rotor, vector ^ vector,
#   rotor * vector), and the report sends (nearly) none of its calls to the
#   generic path;
# - editing the profile regenerates the algebra;
# - PROFILE and COVERAGE misused stop the configure with a message saying why.
file(GLOB two_pass "${WORK_DIR}/install/lib*/cmake/gaphys/GaphysTwoPass.cmake")
file(GLOB generator "${WORK_DIR}/install/share/gaphys/generator/gaphys-gen")
if(NOT two_pass OR NOT generator)
  message(FATAL_ERROR "the package lacks GaphysTwoPass.cmake ('${two_pass}') or gaphys-gen ('${generator}')")
endif()
set(app "${SOURCE_DIR}/examples/consumer")
set(build "${WORK_DIR}/build")
run("${CMAKE_COMMAND}" "-DBUILD_DIR=${build}" "-DSOURCE_DIR=${app}"
    "-DCONFIGURE_ARGS=-G '${GENERATOR}' '-DCMAKE_PREFIX_PATH=${WORK_DIR}/install' '-DPython3_EXECUTABLE=${PYTHON}'"
    -P "${two_pass}" -- ./consumer_app)
run("${build}/consumer_app")

# The first pass was instrumented, the second optimized with the merged profile.
set(profile "${build}/gaphys-two-pass/profiles/e2ga.json")
file(STRINGS "${build}/gaphys-two-pass/instrumented/plane_algebra_generated/e2ga/e2ga.hpp" variant
     REGEX "^// Variant:")
if(NOT variant STREQUAL "// Variant: instrumented")
  message(FATAL_ERROR "the first pass built e2ga as '${variant}', not instrumented")
endif()
set(specialized "${build}/plane_algebra_generated/e2ga/specialized.hpp")
file(READ "${specialized}" text)
string(REGEX MATCH "\n// Profile: [^\n]*" banner "${text}")
if(NOT banner MATCHES "^\n// Profile: (.*) \\(([0-9]+) calls; ([0-9]+) mv kernels at coverage 0.999\\)$"
   OR NOT CMAKE_MATCH_1 STREQUAL profile OR CMAKE_MATCH_2 LESS 1000 OR CMAKE_MATCH_3 LESS 1)
  message(FATAL_ERROR "${specialized}: expected a banner naming ${profile}, its calls (at least the "
                      "workload's 1000 steps) and mv kernels; got '${banner}'")
endif()
message(STATUS "e2ga two-pass: ${CMAKE_MATCH_2} calls profiled, ${CMAKE_MATCH_3} mv kernels")
# Blade bits: 1 -> 0x1, e1 -> 0x2, e2 -> 0x4, e1^e2 -> 0x8; a rotor is 0x9, a vector 0x6.
foreach(combination "\"gp\", 0x9u, 0x9u" "\"op\", 0x6u, 0x6u" "\"gp\", 0x9u, 0x2u")
  string(FIND "${text}" "{${combination}," at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${specialized}: no mv kernel for the workload's {${combination}}")
  endif()
endforeach()
execute_process(COMMAND "${PYTHON}" "${generator}" report "${profile}" --spec "${app}/e2ga.ga" --coverage 0.999
                OUTPUT_VARIABLE report RESULT_VARIABLE failed)
string(REGEX MATCH "specialized at coverage 0.999: [0-9]+ combinations, ([0-9]+) calls;.*generic fallback: ([0-9]+) calls"
       line "${report}")
if(failed OR NOT line OR CMAKE_MATCH_1 LESS 1000 OR CMAKE_MATCH_2 GREATER CMAKE_MATCH_1)
  message(FATAL_ERROR "gaphys-gen report ${profile}: expected at least 1000 specialized calls and fewer "
                      "left to the generic fallback; got:\n${report}")
endif()
message(STATUS "e2ga two-pass report: ${line}")

# Editing the profile regenerates the algebra.
file(TOUCH "${profile}")
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${build}" OUTPUT_VARIABLE output RESULT_VARIABLE failed)
if(failed OR NOT output MATCHES "gaphys: generating e2ga \\(optimized, profile ")
  message(FATAL_ERROR "a touched profile did not regenerate e2ga:\n${output}")
endif()

# PROFILE and COVERAGE misused: a configure error that says why.
set(bad "${WORK_DIR}/bad_profile")
file(WRITE "${bad}/CMakeLists.txt"
     "cmake_minimum_required(VERSION 3.25)\n"
     "project(bad_profile NONE)\n"
     "find_package(gaphys REQUIRED)\n"
     "separate_arguments(arguments UNIX_COMMAND \"\${ARGUMENTS}\")\n"
     "gaphys_add_algebra(TARGET plane SPEC \"${app}/e2ga.ga\" \${arguments})\n")
foreach(case
    "VARIANT reference PROFILE '${profile}'|PROFILE goes with VARIANT optimized, not reference"
    "PROFILE '${WORK_DIR}/missing.json'|profile '${WORK_DIR}/missing.json' not found"
    "PROFILE '${WORK_DIR}'|profile '${WORK_DIR}' is a folder, not a profile file"
    "COVERAGE 0.5|COVERAGE 0.5 needs a PROFILE"
    "PROFILE '${profile}' COVERAGE 2|COVERAGE must be a share of calls in \\(0, 1\\], not '2'")
  string(REPLACE "|" ";" case "${case}")
  list(GET case 0 arguments)
  list(GET case 1 expected)
  file(REMOVE_RECURSE "${bad}/build")
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${bad}" -B "${bad}/build" -G "${GENERATOR}"
                          "-DCMAKE_PREFIX_PATH=${WORK_DIR}/install" "-DPython3_EXECUTABLE=${PYTHON}"
                          "-DARGUMENTS=${arguments}"
                  RESULT_VARIABLE failed OUTPUT_QUIET ERROR_VARIABLE errors)
  string(REPLACE "\n" " " errors "${errors}")
  string(REGEX REPLACE " +" " " errors "${errors}")
  if(NOT failed OR NOT errors MATCHES "${expected}")
    message(FATAL_ERROR "gaphys_add_algebra(... ${arguments}): expected a configure error matching "
                        "'${expected}'; got exit ${failed}:\n${errors}")
  endif()
endforeach()
