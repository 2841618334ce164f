#!/usr/bin/env bash
# Writes the MCAP test bags (tests/node/make_test_bags.mjs, make_cloud_bags.mjs and make_display_bags.mjs, with the MCAP
# project's own writer) into OUT_DIR, installing the npm packages first when needed. ctest runs it as the fixture of every test
# that reads bags; the benchmarks run it with --large.
# usage: scripts/make-test-bags.sh OUT_DIR [--large]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/node-deps.sh"
node "$root/tests/node/make_test_bags.mjs" "$@"
node "$root/tests/node/make_cloud_bags.mjs" "$1"
node "$root/tests/node/make_display_bags.mjs" "$1"
