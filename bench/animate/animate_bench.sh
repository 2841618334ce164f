#!/usr/bin/env bash
# Throughput and peak memory of `urdfsnap animate` for mrm at 640x480 (one process: the robot
# prepared once, render and encode overlapping on two threads), beside a single `urdfsnap render`
# process in the same run: per output format, 1,000 frames of a moving arm (wall time, frames/s,
# CPU time of all threads per frame, peak resident memory, output size); then the peak memory of
# 100 and 10,000 frames, which must not differ by more than noise. On a shared machine wall time
# follows the load (printed first); CPU ms per frame is the load-independent figure.
# usage: bench/animate/animate_bench.sh URDFSNAP [FRAMES]   (FRAMES default 1000)
set -euo pipefail
snap=$1
frames=${2:-1000}
source "$(dirname "$0")/../bench_work.sh" animate_bench
model=$root/models/mrm_description/urdf/mrm.urdf

# every joint of mrm swinging, a waypoint a second for 400 s (enough for 10,000 frames at 30/s)
awk 'BEGIN {
  print "time,base_link__link_01,link_01__link_02,link_02__link_03,link_03__link_04,link_04__link_05";
  for (t = 0; t <= 400; ++t)
    printf "%d,%.4f,%.4f,%.4f,%.4f,%.4f\n", t, 2.5 * sin(0.7 * t), 1.2 * sin(1.1 * t + 1),
           1.4 * sin(0.9 * t + 2), 2 * sin(1.3 * t), 2.5 * sin(0.5 * t + 3) }' >"$work/motion.csv"

# run NAME OUTPUT FRAMES [OPTIONS...]: one animate run, its figures as a table row
run() {
  local name=$1 output=$2 count=$3
  shift 3
  rm -rf "$work/out" && mkdir -p "$work/out"
  local duration
  duration=$(awk "BEGIN {print ($count - 1) / 30}")
  /usr/bin/time -f '%e %U %S %M' -o "$work/time" "$snap" animate "$model" --trajectory "$work/motion.csv" \
    --fps 30 --duration "$duration" --fit --no-shard --jobs 1 -o "$work/out/$output" --quiet "$@"
  read -r wall user sys rss <"$work/time"
  printf '%-12s %7d %8.2f %9.0f %8.2f %8.2f %8.0f %8.1f\n' "$name" "$count" "$wall" \
    "$(awk "BEGIN {print $count / $wall}")" "$(awk "BEGIN {print $user + $sys}")" \
    "$(awk "BEGIN {print 1000 * ($user + $sys) / $count}")" "$(awk "BEGIN {print $rss / 1024}")" \
    "$(du -sk "$work/out" | awk '{print $1 / 1024}')"
}

echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
printf '%-12s %7s %8s %9s %8s %8s %8s %8s\n' output frames "wall s" "frames/s" "cpu s" "cpu ms/f" "peak MB" "out MB"
/usr/bin/time -f '%e %U %S %M' -o "$work/time" "$snap" render "$model" --fit -o "$work/one.png"
read -r wall user sys rss <"$work/time"
printf '%-12s %7d %8.2f %9.1f %8.2f %8.2f %8.0f %8s\n' "render" 1 "$wall" "$(awk "BEGIN {print 1 / $wall}")" \
  "$(awk "BEGIN {print $user + $sys}")" "$(awk "BEGIN {print 1000 * ($user + $sys)}")" \
  "$(awk "BEGIN {print $rss / 1024}")" "-"
run "png" "%05d.png" "$frames"
run "mp4" "a.mp4" "$frames"
run "webm" "a.webm" "$frames"
run "gif" "a.gif" "$frames"
run "webp" "a.webp" "$frames"
run "png+depth" "%05d.png" "$frames" --depth "$work/out/d%05d.png" --labels "$work/out/l%05d.png"
echo "peak memory by length:"
for format in mp4 gif webp; do
  run "$format" "a.$format" 100
  run "$format" "a.$format" 10000
done
