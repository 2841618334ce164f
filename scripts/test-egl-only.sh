#!/usr/bin/env bash
# CI's EGL-only stage (scripts/test.sh runs it when CI=true): builds urdfsnap without OSMesa
# (-DURDFSNAP_WITH_OSMESA=OFF, as on distributions whose Mesa, 25.1 on, has no OSMesa) into
# build-egl/ and runs the whole test suite there, every image drawn through EGL. No benchmarks.
# usage: scripts/test-egl-only.sh [ctest args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-egl
"$root/scripts/deps.sh"
# through ccache, as scripts/build.sh: only the GL library and what includes its options differ
export CCACHE_BASEDIR=$root
(cd "$root" && cmake --preset egl-only >/dev/null)   # CMakePresets.json
cmake --build "$build" -j "$(nproc)" >/dev/null
(cd "$build" && ctest --output-on-failure -j "$(nproc)" "$@")
