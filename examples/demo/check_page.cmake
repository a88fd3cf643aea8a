# ctest demo_html_page: gaphys_demo --html writes a whole page, as text: the
# template with three.js, the scene and the trajectory in place of its
# placeholders, and no temporary file left (demo_viewer looks at it in a browser).
# Inputs: DEMO, WORK_DIR.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(page "${WORK_DIR}/page.html")
execute_process(COMMAND "${DEMO}" --scene bouncing_sphere --steps 24 --every 12 --html "${page}"
                RESULT_VARIABLE code OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "gaphys_demo --html: exit code ${code}\n${errors}")
endif()
if(NOT output STREQUAL "")
  message(FATAL_ERROR "gaphys_demo --html without --out wrote to standard output:\n${output}")
endif()
file(READ "${page}" text)
# The placeholders are each an at sign, GAPHYS_, a name and an at sign.
set(at "@")
foreach(wanted IN ITEMS "<!DOCTYPE html>" "</html>" "REVISION"
                        "{\"scene\": \"bouncing_sphere\", \"description\": "
                        "{\"id\": 0, \"static\": true, \"shape\": {\"kind\": \"plane\", \"normal\": [0, 0, 1], \"offset\": 0}"
                        "{\"id\": 1, \"static\": false, \"shape\": {\"kind\": \"sphere\", \"radius\": 0.5}, \"shapes\": [{\"kind\": \"sphere\", \"radius\": 0.5, \"position\": [0, 0, 0], \"attitude\": [1, 0, 0, 0]}]"
                        "{\"scene\": \"bouncing_sphere\", \"time_step\": "
                        "{\"time\": 0.1")
  string(FIND "${text}" "${wanted}" where)
  if(where EQUAL -1)
    message(FATAL_ERROR "${page} lacks '${wanted}'")
  endif()
endforeach()
# The frame at 0.1 s: 24 steps of 1/240 s, which a float engine's step
# (1/240 to 7 digits) brings to 0.1000000016.
if(NOT text MATCHES "\\{\"time\": 0\\.1(0000000[0-9]*)?, \"bodies\": \\[\\{\"id\": 1, ")
  message(FATAL_ERROR "${page} lacks the frame at 0.1 s")
endif()
string(FIND "${text}" "${at}GAPHYS_" where)
if(NOT where EQUAL -1)
  message(FATAL_ERROR "${page} still has a placeholder at byte ${where}")
endif()
file(GLOB left RELATIVE "${WORK_DIR}" "${WORK_DIR}/*")
if(NOT left STREQUAL "page.html")
  message(FATAL_ERROR "${WORK_DIR} holds [${left}], not just page.html")
endif()
