#!/usr/bin/env bash
# Regenerates the golden images in tests/golden/ from the current build (after an intended change).
# Look at every rewritten image before committing it.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
cd "$root/build"
URDFSNAP_UPDATE_GOLDEN=1 ctest -L golden --output-on-failure
git -C "$root" status --short tests/golden
