# ctest helper: --out through a symbolic link replaces the file the link
# names and leaves the link a link (renaming over the link itself put a plain
# file in its place). Inputs: DEMO, WORK_DIR.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/data")
file(WRITE "${WORK_DIR}/data/run.csv" "old\n")
file(CREATE_LINK "data/run.csv" "${WORK_DIR}/run.csv" SYMBOLIC)

execute_process(COMMAND "${DEMO}" --scene box_tower --steps 2 --out "${WORK_DIR}/run.csv"
                RESULT_VARIABLE code ERROR_VARIABLE errors)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "gaphys_demo failed (${code}):\n${errors}")
endif()
if(NOT IS_SYMLINK "${WORK_DIR}/run.csv")
  message(FATAL_ERROR "${WORK_DIR}/run.csv is no longer a symbolic link")
endif()
file(STRINGS "${WORK_DIR}/data/run.csv" header LIMIT_COUNT 1)
if(NOT header MATCHES "^time,body,x,y,z")
  message(FATAL_ERROR "the file the link names was not replaced: its first line is '${header}'")
endif()
file(GLOB left RELATIVE "${WORK_DIR}" "${WORK_DIR}/*" "${WORK_DIR}/data/*")
list(SORT left)
if(NOT left STREQUAL "data;data/run.csv;run.csv")
  message(FATAL_ERROR "files left: [${left}]")
endif()
