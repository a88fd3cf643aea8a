#!/usr/bin/env bash
# Runs every test: the generator's Python tests, generated/ freshness, the
# algebra tests on both variants (float and double), the ganja.js oracle, and
# an app built against the installed package (all through ctest). Run tools/setup.sh once first.
set -euo pipefail
cd "$(dirname "$0")/.."

python=$(bash tools/find-python.sh)
cmake -S . -B build -G Ninja -DPython3_EXECUTABLE="$python"
cmake --build build
ctest --test-dir build --output-on-failure -j2


# The same GoogleTest suites (reference and optimized) under ASan + UBSan.
bash tools/test-sanitized.sh
