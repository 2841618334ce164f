#!/usr/bin/env bash
# The issue's speed figure for bags: a 60 s, 100 Hz recording of the rover sample (joint states and
# odom -> base_link on /tf, its description inside) to a 30 fps MP4, against the same 1,801 frames
# from a CSV of the same joint values (the robot then stays at the origin): the bag may take at
# most 1.5 times as long. Runs alternate, and CPU time of all threads (user + sys) is compared as
# well as wall time, since wall time follows the load of a shared machine.
# usage: bench/animate/bag_vs_csv_bench.sh URDFSNAP BAGS [RUNS]
#   BAGS: a folder with rover_loop_60s.mcap (scripts/make-test-bags.sh BAGS --large writes it)
set -euo pipefail
snap=$1
bag=$2/rover_loop_60s.mcap
runs=${3:-3}
source "$(dirname "$0")/../bench_work.sh" bag_bench
model=$root/models/rover_description/urdf/rover.urdf

# the joint values the bag holds (tests/node/make_test_bags.mjs, roverLoop(60, 100))
awk 'BEGIN {
  pi = atan2(0, -1);
  print "time,front_left_wheel_joint,rear_left_wheel_joint,front_right_wheel_joint,rear_right_wheel_joint,head_pan_joint";
  for (i = 0; i <= 6000; ++i) {
    t = i / 100; h = 2 * pi * t / 60; l = h * 0.77 / 0.1; r = h * 1.23 / 0.1;
    printf "%.2f,%.17g,%.17g,%.17g,%.17g,%.17g\n", t, l, l, r, r, sin(2 * h) } }' >"$work/rover.csv"

view=(--size 320x240 --yaw 0.6 --pitch 0.7 --distance 4.5 --focal 0,1,0 --fps 30 --quiet)
# one run: prints wall and CPU seconds
run() {
  /usr/bin/time -f '%e %U %S' -o "$work/time" "$snap" animate "$@" "${view[@]}" -o "$work/out.mp4"
  awk '{printf "%.2f %.2f\n", $1, $2 + $3}' "$work/time"
}
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
printf '%-4s %-26s %-26s\n' run "bag (wall s, CPU s)" "CSV (wall s, CPU s)"
for ((k = 1; k <= runs; ++k)); do
  bag_times=$(run "$bag" --fixed-frame odom)
  csv_times=$(run "$model" --trajectory "$work/rover.csv")
  printf '%-4s %-26s %-26s\n' "$k" "$bag_times" "$csv_times"
done
