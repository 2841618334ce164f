#!/usr/bin/env bash
# Installs the npm packages of urdfsnap's test tooling (tests/node/package.json: the MCAP writer and
# ROS 2 serialiser that make the test bags, playwright-core for the live view's browser test) into
# tests/node/node_modules (git-ignored), exactly as package-lock.json pins them, when they are
# missing or the lock file has changed since. Quiet when they are up to date. Test-only: nothing
# urdfsnap runs needs node.
# usage: scripts/node-deps.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$root/tests/node
stamp=$dir/node_modules/.urdfsnap-lock-stamp
# several test processes may call this at once: one installs, the others wait for it
exec 9>"$dir/.install-lock"
flock 9
if [ -f "$stamp" ] && cmp -s "$stamp" "$dir/package-lock.json"; then exit 0; fi
if ! command -v npm >/dev/null; then
  echo "node-deps.sh: npm is missing (scripts/deps.sh installs nodejs and npm)" >&2
  exit 1
fi
echo "node-deps.sh: installing the test tooling's npm packages into $dir/node_modules" >&2
(cd "$dir" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
cp "$dir/package-lock.json" "$stamp"
