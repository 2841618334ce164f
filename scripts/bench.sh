#!/usr/bin/env bash
# Builds urdfsnap and runs its benchmarks, printing their tables (the C++ ones, then the time and
# memory of whole commands, start-up among them, the published robots last: set
# URDFSNAP_FRANKA_DESCRIPTION and URDFSNAP_PR2_DESCRIPTION, see bench/robots/robots_bench.sh).
# Timings only; nothing asserts.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
for b in "$root"/build/*_bench; do
  [ -x "$b" ] || continue
  echo "== $(basename "$b")"
  "$b"
done
echo "== docs_bench"
"$root/bench/docs/docs_bench.sh" "$root/build/urdfsnap"
echo "== startup_bench"
"$root/bench/startup/startup_bench.sh" "$root/build/urdfsnap"
echo "== robots_bench"
"$root/bench/robots/robots_bench.sh" "$root/build/urdfsnap"
