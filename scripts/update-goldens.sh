#!/usr/bin/env bash
# Regenerates the golden images of tests/golden/suite.yaml from the current build after an
# intended change: cases that are missing or no longer match (all with --force; only some with
# their names). Look at every rewritten image before committing it.
# usage: scripts/update-goldens.sh [--force] [CASE...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
"$root/build/urdfsnap" snapshot update "$root/tests/golden/suite.yaml" "$@"
git -C "$root" status --short tests/golden
