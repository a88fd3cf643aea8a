# gaphys_inline_copies: compile options under which GCC on x86-64 copies and
# clears small structs with plain moves instead of `rep movs` / `rep stos`.
#
# GCC's generic tuning expands a copy or a clear of known size from 32 bytes
# to 8 KiB into a string instruction, which takes some thirty cycles to
# start on cores without fast short `rep` (Intel before Ice Lake; the
# 2-core Xeon of docs/benchmarks.md). The engine clears and copies a few
# such structs per contact and per body in every step: a constraint (104
# bytes) and its impact terms (96) as it is built, a contact (248) as the
# narrow phase makes it, a placed shape. There the string instructions'
# start-up took a quarter of building the constraints, and the whole step of
# 1,000 spheres ran 3% faster without them. Up to 512 bytes an unrolled
# loop of moves; beyond, and where the size is known only at run time, the C
# library's memcpy and memset, as before. Clang does not expand these into
# string instructions. Nothing here changes a computed value.
include(CheckCXXCompilerFlag)

add_library(gaphys_inline_copies INTERFACE)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  set(gaphys_copy_strategy "unrolled_loop:512:noalign,libcall:-1:noalign")
  check_cxx_compiler_flag("-mmemcpy-strategy=${gaphys_copy_strategy}"
                          GAPHYS_HAS_COPY_STRATEGY)
  if(GAPHYS_HAS_COPY_STRATEGY)
    target_compile_options(gaphys_inline_copies INTERFACE
                           -mmemcpy-strategy=${gaphys_copy_strategy}
                           -mmemset-strategy=${gaphys_copy_strategy})
  endif()
endif()
