#!/usr/bin/env bash
# Regenerates the golden images of urdfsnap's snapshot suites (tests/golden/suite.yaml and the
# example project's) from the current build after an intended change: the cases that are missing
# or no longer match, all of them with --force: colour PNGs, and the depth and label goldens
# (NAME.depth.png, NAME.labels.png with NAME.labels.json) of cases with `depth: true` or
# `labels: true`. Look at every rewritten image before committing it (16-bit depth and labels
# look black in a viewer: `urdfsnap snapshot check SUITE --report DIR` before updating shows them
# in colour).
# One suite's named cases: build/urdfsnap snapshot update SUITE CASE...
# usage: scripts/update-goldens.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
for suite in tests/golden/suite.yaml examples/snapshot-testing/snapshots/suite.yaml; do
  "$root/build/urdfsnap" snapshot update "$root/$suite" "$@"
done
git -C "$root" status --short tests/golden examples/snapshot-testing/snapshots
