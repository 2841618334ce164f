#!/usr/bin/env bash
# The live view's page in headless Chromium (tests/node/serve_page_browser.mjs), started on a broken
# model the page then sees mended, then what the page copied
# checked with urdfsnap itself: the suite case passes `snapshot check` against the frame the page
# showed, and the pose file renders. Without chromium: skips (exit 77), or fails when CI=true.
# usage: tests/serve/serve_page_browser.sh URDFSNAP_BINARY [SCREENSHOT.png]
set -euo pipefail
urdfsnap=$1
screenshot=${2:-}
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/tests/node/require_browser.sh"
require_browser "$root"
work=$(mktemp -d "${TMPDIR:-/tmp}/urdfsnap_serve_page.XXXXXX")
server=
cleanup() { [ -n "$server" ] && kill -KILL "$server" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
# the server starts on a broken model (base_link twice); the page mends it by writing the good one
cp "$root/models/mrm_description/urdf/mrm.urdf" "$work/mrm.good.urdf"
sed 's|</robot>|<link name="base_link"/></robot>|' "$work/mrm.good.urdf" >"$work/mrm.urdf"
"$urdfsnap" serve "$work/mrm.urdf" --port 0 >"$work/out" 2>"$work/err" &
server=$!
for _ in $(seq 100); do grep -qs serving "$work/out" && break; sleep 0.1; done
url=$(sed -n 's|^urdfsnap: serving \(http://.*\)$|\1|p' "$work/out")
[ -n "$url" ] || { echo "the server did not start:"; cat "$work/err"; exit 1; }
node --single-threaded "$root/tests/node/serve_page_browser.mjs" "$url" "$work/mrm.urdf" "$work/mrm.good.urdf" "$work"

# the copied suite case renders the frame the page showed
{ echo "cases:"; cat "$work/case.yaml"; } >"$work/suite.yaml"
cp "$work/frame.png" "$work/mrm_view.png"
"$urdfsnap" snapshot check "$work/suite.yaml"
# the copied pose is a joint file render reads
"$urdfsnap" render "$work/mrm.urdf" --joints "$work/pose.yaml" -o "$work/pose.png"
[ -n "$screenshot" ] && cp "$work/page.png" "$screenshot"

kill -INT "$server"
status=0
wait "$server" || status=$?
server=
[ "$status" -eq 0 ] || { echo "urdfsnap serve ended with status $status after SIGINT"; exit 1; }
grep -q "urdfsnap: stopped" "$work/err"
echo "page test passed"
