#!/usr/bin/env bash
# The engine's optimized suite built for this machine's own instruction set
# (-march=native), where the contact sweeps' batches are as wide as its
# vector registers (4 doubles with AVX2, 8 with AVX-512; the default build
# targets the x86-64 baseline, 2) and where multiplies and adds can fuse:
# the batches must still step to the same bits as one contact at a time
# (test_contact_batches.cpp), and every closed form must hold.
# tools/test.sh runs it after the sanitized suites. Built file by file (no
# unity build, unlike the other two builds): a source that compiles only
# beside the others of its batch fails here.
set -euo pipefail
cd "$(dirname "$0")/.."

python=$(bash tools/find-python.sh)
cmake -S . -B build-native -G Ninja -DPython3_EXECUTABLE="$python" \
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS=-march=native \
      -DGAPHYS_BUILD_BENCHMARKS=OFF -DGAPHYS_BUILD_EXAMPLES=OFF
cmake --build build-native --target engine_tests_optimized
ctest --test-dir build-native -j2 --output-on-failure -R '^engine_optimized/'
