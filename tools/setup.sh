#!/usr/bin/env bash
# Installs what is missing on a fresh Debian machine, builds gaphys and runs
# the demos. Safe to run again: it installs only what is not there.
set -euo pipefail
cd "$(dirname "$0")/.."

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

missing=()
for tool in cmake:cmake ninja:ninja-build g++:g++ pkg-config:pkg-config clang-format:clang-format node:nodejs npm:npm; do
  command -v "${tool%%:*}" >/dev/null 2>&1 || missing+=("${tool##*:}")
done
# Bullet, ODE and gnuplot: bench/compare (gaphys against other engines).
# libccd: the convex narrow phase's test oracle (GJK/EPA/MPR).
# Chromium: the demo_viewer test opens gaphys_demo --html pages headless.
for package in libgtest-dev libgmock-dev libbenchmark-dev libbullet-dev libode-dev libccd-dev gnuplot-nox chromium; do
  dpkg -s "$package" >/dev/null 2>&1 || missing+=("$package")
done
python=$(bash tools/find-python.sh)
if ! "$python" -c "import jinja2" 2>/dev/null; then
  missing+=(python3 python3-jinja2)
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  as_root apt-get update -q
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${missing[@]}"
fi

# The ganja.js oracle (tests) and three.js (gaphys_demo --html), pinned by
# package-lock.json.
npm ci --no-audit --no-fund --loglevel=error
python=$(bash tools/find-python.sh)

bash tools/configure.sh
cmake --build build
./build/examples/algebra_demo
./build/examples/demo/gaphys_demo --scene bouncing_sphere --steps 480 --every 240
