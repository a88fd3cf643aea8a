# ctest: gaphys configured with GAPHYS_ENGINE_PROFILE_DIR generates the
# optimized e3ga and c3ga at build time from specs/ and the profiles there.
# Given the committed profiles, that is the committed generated/optimized/
# but for the banner lines naming paths; it is what gets installed; a
# touched profile regenerates; a folder without profiles is a configure error.
# Inputs: SOURCE_DIR, WORK_DIR, PYTHON, GENERATOR.
file(REMOVE_RECURSE "${WORK_DIR}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE failed OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(failed)
    string(REPLACE ";" " " shown "${ARGN}")
    message(FATAL_ERROR "failed: ${shown}\n${output}")
  endif()
  set(output "${output}" PARENT_SCOPE)
endfunction()

set(profiles "${WORK_DIR}/profiles")
file(COPY "${SOURCE_DIR}/profiling/profiles/e3ga.json" "${SOURCE_DIR}/profiling/profiles/c3ga.json"
     DESTINATION "${profiles}")
set(build "${WORK_DIR}/build")
set(options -G "${GENERATOR}" "-DPython3_EXECUTABLE=${PYTHON}" -DGAPHYS_BUILD_TESTS=OFF
            -DGAPHYS_BUILD_BENCHMARKS=OFF -DGAPHYS_BUILD_EXAMPLES=OFF -DGAPHYS_BUILD_COMPARE=OFF)
run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${build}" ${options} "-DGAPHYS_ENGINE_PROFILE_DIR=${profiles}")
run("${CMAKE_COMMAND}" --build "${build}" --target gaphys_e3ga_optimized_generate gaphys_c3ga_optimized_generate)

# The generated headers: the committed ones but for the lines naming paths.
foreach(algebra e3ga c3ga)
  file(GLOB committed RELATIVE "${SOURCE_DIR}/generated/optimized" "${SOURCE_DIR}/generated/optimized/${algebra}/*")
  file(GLOB made RELATIVE "${build}/generated/optimized" "${build}/generated/optimized/${algebra}/*")
  if(NOT committed STREQUAL made)
    message(FATAL_ERROR "generated ${made}, expected ${committed}")
  endif()
  foreach(header IN LISTS committed)
    file(READ "${SOURCE_DIR}/generated/optimized/${header}" expected)
    file(READ "${build}/generated/optimized/${header}" made)
    string(REGEX REPLACE "// (Spec|Profile|Regenerate): [^\n]*\n" "" expected "${expected}")
    string(REGEX REPLACE "// (Spec|Profile|Regenerate): [^\n]*\n" "" made "${made}")
    if(NOT expected STREQUAL made)
      message(FATAL_ERROR "${build}/generated/optimized/${header} differs from the committed one "
                          "beyond its banner")
    endif()
  endforeach()
endforeach()
file(STRINGS "${build}/generated/optimized/e3ga/specialized.hpp" banner REGEX "^// Profile: ")
if(NOT banner MATCHES "^// Profile: ${profiles}/e3ga.json ")
  message(FATAL_ERROR "e3ga was not generated from ${profiles}/e3ga.json: '${banner}'")
endif()

# The package installs them (building the engine against them, a minute, is
# left to the builds that install it).
file(READ "${build}/cmake_install.cmake" install_script)
foreach(algebra e3ga c3ga)
  string(FIND "${install_script}" "\"${build}/generated/optimized/${algebra}\"" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${build}/cmake_install.cmake does not install ${build}/generated/optimized/${algebra}")
  endif()
endforeach()

# A touched profile regenerates its algebra, and only it.
file(TOUCH "${profiles}/c3ga.json")
run("${CMAKE_COMMAND}" --build "${build}" --target gaphys_e3ga_optimized_generate gaphys_c3ga_optimized_generate)
if(NOT output MATCHES "generating c3ga \\(optimized, profile " OR output MATCHES "generating e3ga")
  message(FATAL_ERROR "touching c3ga.json should regenerate c3ga alone:\n${output}")
endif()

# A folder without profiles.
file(MAKE_DIRECTORY "${WORK_DIR}/empty")
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/empty-build" ${options}
                        "-DGAPHYS_ENGINE_PROFILE_DIR=${WORK_DIR}/empty"
                RESULT_VARIABLE failed OUTPUT_QUIET ERROR_VARIABLE errors)
string(REGEX REPLACE "[ \n]+" " " errors "${errors}")
if(NOT failed OR NOT errors MATCHES "holds neither e3ga.json nor c3ga.json")
  message(FATAL_ERROR "GAPHYS_ENGINE_PROFILE_DIR without profiles: expected a configure error; got "
                      "exit ${failed}:\n${errors}")
endif()
