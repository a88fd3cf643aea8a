#!/usr/bin/env bash
# Generation time, output size and header compile time of every algebra the
# project has a spec for (issue 16's report): specs/*.ga and the test
# fixtures in tests/algebra/specs/, the optimized variant (with the committed
# profile where there is one). Prints a Markdown table.
#   bash tools/generator-report.sh [CXX]
set -euo pipefail
cd "$(dirname "$0")/.."
python=$(bash tools/find-python.sh)
cxx=${1:-g++}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| algebra | dimension | named types | kernels | generate (s) | lines | KB | compile (s) |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for spec in specs/*.ga tests/algebra/specs/*.ga; do
  name=$(basename "$spec" .ga)
  profile=()
  [[ -f profiling/profiles/$name.json ]] && profile=(--profile "profiling/profiles/$name.json" --coverage 0.999)
  start=$(date +%s.%N)
  "$python" generator/gaphys-gen generate "$spec" --variant optimized --out "$work/out" "${profile[@]}" >/dev/null
  generate=$(echo "$(date +%s.%N) - $start" | bc)
  lines=$(cat "$work/out/$name"/*.hpp | wc -l)
  kb=$(( $(cat "$work/out/$name"/*.hpp | wc -c) / 1024 ))
  kernels=$(grep -c '^template <class T>' "$work/out/$name/kernels.hpp" || true)
  dimension=$(grep -m1 '^basis' "$spec" | wc -w)
  types=$(grep -c '^type ' "$spec")
  # A translation unit that includes the algebra and instantiates one kernel.
  printf '#include <%s/%s.hpp>\nint main() { return int(%s::norm2(%s::mv::basis_blade(1))); }\n' \
    "$name" "$name" "$name" "$name" > "$work/tu.cpp"
  start=$(date +%s.%N)
  "$cxx" -std=c++17 -O2 -I"$work/out" -Iruntime/include -c "$work/tu.cpp" -o "$work/tu.o"
  compile=$(echo "$(date +%s.%N) - $start" | bc)
  printf '| %s | %d | %d | %d | %.2f | %d | %d | %.2f |\n' "$name" $((dimension - 1)) "$types" "$kernels" \
    "$generate" "$lines" "$kb" "$compile"
done
