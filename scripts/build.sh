#!/usr/bin/env bash
# Installs missing dependencies, then configures and builds urdfsnap (Release) into build/.
# usage: scripts/build.sh [extra cmake configure args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/deps.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$root/build" -j "$(nproc)"
