#!/usr/bin/env bash
# Configures the build folder `build` the way tools/setup.sh and tools/test.sh
# (and so CI) both use it, so that neither rebuilds what the other built:
# - Ninja, and a Python 3 that has Jinja2 (tools/find-python.sh);
# - RelWithDebInfo with line tables only (-g1): enough for a backtrace's
#   file:line, and 20-30% less compile time than full debug info;
# - the reference and optimized GoogleTest suites left to the sanitized
#   build (tools/test-sanitized.sh), which builds and runs them under ASan and
#   UBSan, instead of compiling the same sources twice.
set -euo pipefail
cd "$(dirname "$0")/.."
python=$(bash tools/find-python.sh)
cmake -S . -B build -G Ninja -DPython3_EXECUTABLE="$python" \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
      -DGAPHYS_SANITIZED_SUITES_ELSEWHERE=ON "$@"
