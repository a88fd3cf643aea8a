#!/usr/bin/env bash
# Runs every test: the generator's Python tests, generated/ freshness, the
# algebra tests on both variants (float and double), the ganja.js oracle, and
# an app built against the installed package (all through ctest). Run tools/setup.sh once first.
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/configure.sh
cmake --build build
ctest --test-dir build --output-on-failure -j2

# The algebra and engine GoogleTest suites of the reference and optimized
# variants, and algebra_variants_agree, built once with ASan + UBSan and run
# there (tools/configure.sh leaves them out of the build above).
bash tools/test-sanitized.sh

# The engine's optimized suite built with -march=native: the contact batches
# as wide as this machine's vectors, and fused multiply-adds within reach.
bash tools/test-native.sh
