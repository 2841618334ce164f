#!/usr/bin/env bash
# The issue's speed figure for displays in animations: "an animation of a bag with a 10 Hz cloud at
# >= 30 frames/s to MP4". The bag (tests/node/make_display_bags.mjs): the mrm arm moving on a moving
# base, a 10 Hz PointCloud2 of POINTS points (default 30,000, a 16-beam lidar's sweep), a 2 Hz Path
# and a MarkerArray, SECONDS long (default 20); animated at 640x480, 30 fps to MP4 with the cloud,
# path and marker displays, against the same animation without displays. Runs alternate; wall and
# CPU (user + sys, all threads) seconds and frames per wall second are printed.
# usage: bench/animate/display_bag_bench.sh URDFSNAP [RUNS [POINTS [SECONDS]]]
set -euo pipefail
snap=$1
runs=${2:-3}
points=${3:-30000}
seconds=${4:-20}
source "$(dirname "$0")/../bench_work.sh" display_bag_bench
"$root/scripts/node-deps.sh"
# --single-threaded: see scripts/make-test-bags.sh
node --single-threaded "$root/tests/node/make_display_bags.mjs" "$work" "$points" "$seconds"
bag=$work/displays_moving.mcap
frames=$((seconds * 30 + 1))

view=(--fixed-frame odom --size 640x480 --yaw 0.6 --pitch 0.5 --distance 8 --focal 0.6,0,0.8 --fps 30 --quiet)
displays=(--display PointCloud2:/cloud --display MarkerArray:/markers --display Path:/path)
# one run: prints wall s, CPU s, frames per wall second
run() {
  /usr/bin/time -f '%e %U %S' -o "$work/time" "$snap" animate "$bag" "$@" "${view[@]}" -o "$work/out.mp4" 2>/dev/null
  awk -v n="$frames" '{printf "%.2f %.2f %.1f\n", $1, $2 + $3, n / $1}' "$work/time"
}
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores; $frames frames, $points points per cloud"
printf '%-4s %-32s %-32s\n' run "displays (wall s, CPU s, fps)" "robot only (wall s, CPU s, fps)"
for ((k = 1; k <= runs; ++k)); do
  with=$(run "${displays[@]}")
  without=$(run)
  printf '%-4s %-32s %-32s\n' "$k" "$with" "$without"
done
