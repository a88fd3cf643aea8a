#!/usr/bin/env bash
# Configures the build folder `build` the way tools/setup.sh and tools/test.sh
# (and so CI) both use it, so that neither rebuilds what the other built:
# - Ninja, and a Python 3 that has Jinja2 (tools/find-python.sh);
# - RelWithDebInfo with line tables only (-g1): enough for a backtrace's
#   file:line, and 20-30% less compile time than full debug info;
# - the algebra's GoogleTest suites (reference and optimized),
#   algebra_variants_agree and the engine's optimized suite left to the
#   sanitized build (tools/test-sanitized.sh), which builds and runs them
#   under ASan and UBSan, instead of compiling the same sources twice (the
#   engine's reference and float suites stay here);
# - unity builds (CMake's CMAKE_UNITY_BUILD, eight sources a batch): each
#   engine variant and each test suite includes the same generated algebras
#   in every file and compiles their inline kernels again in each; a batch
#   compiles them once (this build: 328 -> 242 s from scratch on 2 cores).
#   tools/test-native.sh builds the engine and its suite file by file, so
#   that a source that compiles only beside others still fails CI.
set -euo pipefail
cd "$(dirname "$0")/.."
python=$(bash tools/find-python.sh)
cmake -S . -B build -G Ninja -DPython3_EXECUTABLE="$python" \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
      -DGAPHYS_SANITIZED_SUITES_ELSEWHERE=ON -DCMAKE_UNITY_BUILD=ON "$@"
