# ctest helper: runs the demo with the arguments after "--" and checks that it
# fails with EXIT_CODE and a stderr matching MESSAGE. With WORK_DIR, that
# directory starts empty (but for MAKE_DIRECTORY, made inside it) and must end
# exactly as it started: a failed run leaves no temporary file behind.
# Inputs: DEMO, EXIT_CODE, MESSAGE, optional WORK_DIR and MAKE_DIRECTORY.
set(arguments "")
set(after_separator OFF)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
  if(after_separator)
    list(APPEND arguments "${CMAKE_ARGV${i}}")
  elseif(CMAKE_ARGV${i} STREQUAL "--")
    set(after_separator ON)
  endif()
endforeach()

if(WORK_DIR)
  file(REMOVE_RECURSE "${WORK_DIR}")
  file(MAKE_DIRECTORY "${WORK_DIR}")
  if(MAKE_DIRECTORY)
    file(MAKE_DIRECTORY "${WORK_DIR}/${MAKE_DIRECTORY}")
  endif()
  file(GLOB before RELATIVE "${WORK_DIR}" "${WORK_DIR}/*")
endif()

execute_process(COMMAND "${DEMO}" ${arguments} RESULT_VARIABLE code ERROR_VARIABLE errors
                OUTPUT_QUIET)
string(REPLACE ";" " " shown "${arguments}")
if(NOT code STREQUAL EXIT_CODE)
  message(FATAL_ERROR "gaphys_demo ${shown}: exit code ${code}, expected ${EXIT_CODE}\n${errors}")
endif()
if(NOT errors MATCHES "${MESSAGE}")
  message(FATAL_ERROR "gaphys_demo ${shown}: stderr does not match '${MESSAGE}':\n${errors}")
endif()

if(WORK_DIR)
  file(GLOB after RELATIVE "${WORK_DIR}" "${WORK_DIR}/*")
  if(NOT after STREQUAL before)
    message(FATAL_ERROR "gaphys_demo ${shown} changed ${WORK_DIR}: [${before}] became [${after}]")
  endif()
endif()
