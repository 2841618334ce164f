#!/usr/bin/env bash
# Installs a built urdfsnap into a temporary prefix, then configures, builds and tests the example
# projects in examples/ against it (find_package(urdfsnap) as a user's project does):
# snapshot-testing and cpp-api. (That each installed header compiles alone: the test
# installed_headers, tests/install/.)
# usage: scripts/test-example.sh [BUILD_DIR]   (default: build/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null

for example in snapshot-testing cpp-api; do
  cmake -S "$root/examples/$example" -B "$work/$example" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
  cmake --build "$work/$example" -j "$(nproc)" >/dev/null
  (cd "$work/$example" && ctest --output-on-failure)
done
