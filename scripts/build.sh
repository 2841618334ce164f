#!/usr/bin/env bash
# Installs missing dependencies, then configures and builds urdfsnap (Release) into build/.
# usage: scripts/build.sh [extra cmake configure args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/deps.sh"
# through ccache: a rebuild, and CI's EGL-only build after this one, compile only what changed
export CCACHE_BASEDIR=$root
(cd "$root" && cmake --preset release "$@" >/dev/null)   # CMakePresets.json
cmake --build "$root/build" -j "$(nproc)"
