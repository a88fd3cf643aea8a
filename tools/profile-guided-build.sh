#!/usr/bin/env bash
# The two-pass profile-guided build, end to end:
#   1. build the training workload against the instrumented variant,
#   2. run it, recording profiles of e3ga and c3ga,
#   3. store them as the committed profiles (profiling/profiles/) and
#      regenerate the optimized variant (generated/optimized/) from them,
#   4. build and test (tools/test.sh), the optimized variant being the default.
# COVERAGE (default 0.999) is the share of profiled calls that get straight-line code.
# (For experiments: the tests check the committed generated/optimized/ at
# 0.999, so step 4 fails the generated_up_to_date_* tests at any other.)
set -euo pipefail
cd "$(dirname "$0")/.."
coverage=${COVERAGE:-0.999}
python=$(bash tools/find-python.sh)

cmake -S . -B build-pgo -G Ninja -DPython3_EXECUTABLE="$python" \
      -DGAPHYS_BUILD_TESTS=OFF -DGAPHYS_BUILD_BENCHMARKS=OFF -DGAPHYS_BUILD_EXAMPLES=OFF
cmake --build build-pgo --target train_workload
rm -rf build-pgo/profiles && mkdir -p build-pgo/profiles
GAPHYS_PROFILE_DIR="$PWD/build-pgo/profiles" ./build-pgo/profiling/train_workload

for algebra in e3ga c3ga; do
  "$python" generator/gaphys-gen merge --spec specs/$algebra.ga --out profiling/profiles/$algebra.json \
            build-pgo/profiles/$algebra.json
  "$python" generator/gaphys-gen report profiling/profiles/$algebra.json --spec specs/$algebra.ga \
            --coverage "$coverage" --top 5
  "$python" generator/gaphys-gen generate specs/$algebra.ga --variant optimized --out generated/optimized \
            --profile profiling/profiles/$algebra.json --coverage "$coverage"
done

bash tools/test.sh
