#!/usr/bin/env bash
# Runs every test: the generator's Python tests, generated/ freshness, the
# algebra tests on both variants (float and double), the ganja.js oracle, and
# an app built against the installed package. Run tools/setup.sh once first.
set -euo pipefail
cd "$(dirname "$0")/.."

cmake -S . -B build -G Ninja
cmake --build build
ctest --test-dir build --output-on-failure -j2

# Install, then build and run an app that uses find_package(gaphys) and
# generates its own algebra with gaphys_add_algebra().
rm -rf build/install build/consumer
cmake --install build --prefix build/install >/dev/null
cmake -S examples/consumer -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$PWD/build/install" \
      -DPython3_EXECUTABLE="$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' build/CMakeCache.txt)"
cmake --build build/consumer
./build/consumer/consumer_app
