#!/usr/bin/env bash
# Pages of `urdfsnap docs` in headless Chromium (tests/node/docs_page_browser.mjs) for the project's
# robots, the synthetic 42-joint bigbot and, when ../shared is beside the project, published robots
# the pages were not written for: images load, no console errors, a section per movable joint, the
# README's links resolve to images that decode. Without chromium: skips (exit 77), or fails when CI=true.
# usage: tests/docs/docs_page_browser.sh URDFSNAP_BINARY [SCREENSHOT_DIR]
set -euo pipefail
urdfsnap=$1
shots=${2:-}
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/tests/node/require_browser.sh"
require_browser "$root"
work=$(mktemp -d "${TMPDIR:-/tmp}/urdfsnap_docs_browser.XXXXXX")
trap 'rm -rf "$work"' EXIT

# the movable joints that are not mimics, from `urdfsnap info`, comma-separated
movable() {
  "$urdfsnap" info "$@" | awk '/^joints:/ {on = 1; next} /^$/ {on = 0} on && $2 ~ /^(revolute|continuous|prismatic)$/ && !/mimic/ {print $1}' |
    paste -sd, -
}

status=0
page() {
  local name=$1; shift
  echo "== $name"
  "$urdfsnap" docs "$@" --no-shard -o "$work/$name"
  node --single-threaded "$root/tests/node/docs_page_browser.mjs" "$work/$name" "$(movable "$@")" ${shots:+"$shots/$name.png"} || status=1
}
page mrm "$root/models/mrm_description/urdf/mrm.xacro"
page meshbot "$root/models/meshbot_description/urdf/meshbot.urdf"
page bigbot "$root/tests/data/bigbot/bigbot.urdf.xacro"
real=$root/../shared/rviz-reference/real
if [ -d "$real/urdf" ]; then
  export ROS_PACKAGE_PATH=$(cd "$real/robots" && pwd)
  for robot in gen3 husky; do page "$robot" "$real/urdf/$robot.urdf"; done
fi
exit $status
