#!/usr/bin/env bash
# The committed documentation pages of the project's own robots (docs/robots/NAME/), made by
# `urdfsnap docs`: regenerates them, or with --check compares each with a fresh one (the ctest
# docs_pages_current runs that, so they cannot go stale).
# usage: scripts/docs-pages.sh [--check] [URDFSNAP]   (default: build/urdfsnap, built first)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mode=-o
if [ "${1:-}" = "--check" ]; then mode=--check; shift; fi
snap=${1:-}
if [ -z "$snap" ]; then "$root/scripts/build.sh"; snap=$root/build/urdfsnap; fi
# NAME MODEL: one page per robot in models/
pages=(
  "mrm models/mrm_description/urdf/mrm.xacro"
  "meshbot models/meshbot_description/urdf/meshbot.urdf"
)
status=0
# --no-shard: whole pages even inside a CI job that shards (GitLab parallel:, a Slurm array)
for entry in "${pages[@]}"; do
  read -r name model <<<"$entry"
  "$snap" docs "$root/$model" --no-shard "$mode" "$root/docs/robots/$name" || status=$?
done
exit $status
