#!/usr/bin/env bash
# Time and peak memory of `urdfsnap docs --jobs 1` (one process, one GL context; robots_bench.sh
# times the default worker processes) for mrm, the mesh sample robot and the synthetic 42-joint
# bigbot: wall time, CPU time and peak resident memory, best of 3.
# usage: bench/docs/docs_bench.sh URDFSNAP
set -euo pipefail
snap=$1
source "$(dirname "$0")/../bench_work.sh" docs_bench
printf '%-10s %8s %8s %10s %8s %7s\n' robot "wall s" "cpu s" "peak MB" pictures "page MB"
for entry in "mrm models/mrm_description/urdf/mrm.xacro" "meshbot models/meshbot_description/urdf/meshbot.urdf" \
             "bigbot tests/data/bigbot/bigbot.urdf.xacro"; do
  read -r name model <<<"$entry"
  best=
  for _ in 1 2 3; do
    rm -rf "$work/page"
    /usr/bin/time -f '%e %U %S %M' -o "$work/time" "$snap" docs "$root/$model" --no-shard --jobs 1 -o "$work/page" 2>/dev/null
    read -r wall user sys rss <"$work/time"
    if [ -z "$best" ] || awk "BEGIN {exit !($wall < ${best%% *})}"; then best="$wall $user $sys $rss"; fi
  done
  read -r wall user sys rss <<<"$best"
  pictures=$(find "$work/page" -type f ! -name '*.md' ! -name '*.html' | wc -l)
  size=$(du -sm "$work/page" | cut -f1)
  printf '%-10s %8.2f %8.2f %10.0f %8d %7s\n' "$name" "$wall" "$(awk "BEGIN {print $user + $sys}")" \
    "$(awk "BEGIN {print $rss / 1024}")" "$pictures" "$size"
done
