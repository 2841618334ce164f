#!/usr/bin/env bash
# Installs missing dependencies, builds urdfsnap and runs every test (ctest). With CI=true (as
# .ci/run sets it) two stages follow: the build without OSMesa, every test through EGL alone
# (scripts/test-egl-only.sh), and the sanitizer stage: the whole suite again under ASan+UBSan
# and each fuzz target for a short time (scripts/test-sanitizers.sh).
# usage: scripts/test.sh [ctest args...]   e.g. scripts/test.sh -L unit
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
# the browser tests run in headless Chromium (in CI a missing browser fails them)
echo "test.sh: browser tests with $(chromium --version 2>/dev/null || echo 'no chromium (they will be skipped, or fail in CI)')"
(cd "$root/build" && ctest --output-on-failure -j "$(nproc)" "$@")
if [ "${CI:-}" = true ]; then
  "$root/scripts/test-egl-only.sh"
  "$root/scripts/test-sanitizers.sh"
fi
