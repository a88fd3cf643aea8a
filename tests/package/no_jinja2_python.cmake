# gaphys_no_jinja2_python(<dir> <python>): writes <dir>/python3, which runs
# <python> without site-packages (-S), where Jinja2 lives, and checks that it
# cannot import jinja2 (else a test relying on it would prove nothing). Put
# <dir> first on PATH to show that a step needs no generator.
function(gaphys_no_jinja2_python dir python)
  file(WRITE "${dir}/python3" "#!/bin/sh\nexec \"${python}\" -S -E \"$@\"\n")
  file(CHMOD "${dir}/python3" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
  execute_process(COMMAND "${dir}/python3" -c "import jinja2" RESULT_VARIABLE no_jinja2
                  OUTPUT_QUIET ERROR_QUIET)
  if(NOT no_jinja2)
    message(FATAL_ERROR "${dir}/python3 can import jinja2; the check relying on it would prove nothing")
  endif()
endfunction()
