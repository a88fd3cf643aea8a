#!/usr/bin/env bash
# The GoogleTest suites of the algebras in the reference and optimized
# variants, algebra_variants_agree (the two variants call by call, and every
# profiled and superset kernel) and the engine's suite on the optimized
# variant, built with AddressSanitizer and UndefinedBehaviorSanitizer
# (-DGAPHYS_SANITIZE=ON): any report aborts its test, and so fails this
# script. tools/test.sh runs it after the main suite. (The engine's code is
# the same on every variant; its suite on the reference variant runs in the
# main build, unsanitized.)
set -euo pipefail
cd "$(dirname "$0")/.."

python=$(bash tools/find-python.sh)
targets=(algebra_tests_reference algebra_tests_optimized algebra_variants_agree
         algebra_fixture_tests_reference algebra_fixture_tests_optimized
         engine_tests_optimized)
# (Unity builds as in tools/configure.sh: each suite's files in batches;
# algebra_variants_agree's, with options of their own, file by file.)
cmake -S . -B build-asan -G Ninja -DPython3_EXECUTABLE="$python" -DGAPHYS_SANITIZE=ON \
      -DGAPHYS_BUILD_BENCHMARKS=OFF -DGAPHYS_BUILD_EXAMPLES=OFF -DCMAKE_UNITY_BUILD=ON
cmake --build build-asan --target "${targets[@]}"
# halt_on_error is ASan's default; detect_leaks catches memory the engine loses.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan -j2 --output-on-failure \
      -R '^(reference|optimized|variants_agree|engine_optimized)/'
