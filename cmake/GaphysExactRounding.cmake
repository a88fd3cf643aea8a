# gaphys_exact_rounding: compile options under which every floating-point
# operation the engine writes is rounded on its own, as written.
#
# The contact sweeps on SIMD batches and one contact at a time compute the
# same to the bit (engine/src/contact_batch.hpp), and a step is the same on
# any number of threads, only if no translation unit fuses a multiply and an
# add where another does not. Two things fuse on a target with FMA (any
# -march=native build on x86 since 2013):
# - GCC contracts a * b + c into one FMA by default (-ffp-contract=fast);
# - GCC 12's SLP vectorizer fuses a multiply into an add/subtract pair
#   (vfmaddsub) even under -ffp-contract=off: an engine built with
#   -march=native rounded a friction impulse one unit in the last place
#   differently on batches than one by one.
# The engine and the tests that include its internals (the solver's inline
# functions are instantiated in both, and the linker keeps one copy) link
# this target. On a target without FMA (the x86-64 baseline) nothing can
# fuse and the SLP vectorizer stays on.
include(CheckCXXSourceCompiles)

add_library(gaphys_exact_rounding INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(gaphys_exact_rounding INTERFACE -ffp-contract=off)
endif()
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  check_cxx_source_compiles([=[
#if !defined(__FMA__) && !defined(__AVX512F__) && !defined(__ARM_FEATURE_FMA)
#error "no fused multiply-add on this target"
#endif
int main() { return 0; }
]=] GAPHYS_TARGET_HAS_FMA)
  if(GAPHYS_TARGET_HAS_FMA)
    target_compile_options(gaphys_exact_rounding INTERFACE -fno-tree-slp-vectorize)
  endif()
endif()
add_library(gaphys::exact_rounding ALIAS gaphys_exact_rounding)
