#!/usr/bin/env bash
# Scores urdfsnap against some of the real-RViz display scenes of ../shared/rviz-reference/displays
# (their score.sh scores a folder of scenes): the named scenes are linked into a temporary folder
# of that layout (with `real/` beside it, where the scenes' package_path points) and scored there, so that the scenes urdfsnap draws completely are tested while
# the others are still being built.
# usage: score-display-scenes.sh DISPLAYS_DIR URDFSNAP SCENE...
set -eu
displays=$1 tool=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/displays/scenes"
ln -s "$(cd "$displays/.." && pwd)/real" "$work/real"
for scene in "$@"; do ln -s "$displays/scenes/$scene" "$work/displays/scenes/$scene"; done
"$displays/score.sh" "$work/displays" "$tool"
