#!/usr/bin/env bash
# Writes the MCAP test bags (tests/node/make_test_bags.mjs, make_cloud_bags.mjs and make_display_bags.mjs, with the MCAP
# project's own writer) into OUT_DIR, installing the npm packages first when needed. ctest runs it as the fixture of every test
# that reads bags; the benchmarks run it with --large.
# usage: scripts/make-test-bags.sh OUT_DIR [--large]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/node-deps.sh"
# --single-threaded: V8 without background tasks. Node 20's V8 deadlocks now and then at exit (the
# main thread drains platform tasks while a concurrent TurboFan job waits for a GC only the main
# thread can run; 2 hangs in 24 runs on 2 loaded cores, none in 30 with the flag), which CI saw as
# this fixture timing out after the bags were written.
node --single-threaded "$root/tests/node/make_test_bags.mjs" "$@"
node --single-threaded "$root/tests/node/make_cloud_bags.mjs" "$1"
node --single-threaded "$root/tests/node/make_display_bags.mjs" "$1"
# the display memory test's short and long recordings (tests/cli/display_memory_test.cpp)
node --single-threaded "$root/tests/node/make_display_bags.mjs" "$1" 2000 10 displays_10s.mcap
node --single-threaded "$root/tests/node/make_display_bags.mjs" "$1" 2000 60 displays_60s.mcap
