#!/usr/bin/env bash
# Sets everything up and runs the main job on a bundled example problem: the
# keyhole scene (a long robot that must turn to pass a slot in a wall), showing the
# meshes and checking the problem's start and goal by the exact test and by FCL.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
problem=benchmarks/problems/keyhole.cfg
echo
echo "== freespace info --cfg $problem"
build/bin/freespace info --cfg "$problem"
start=$(awk -F' *= *' '/^start\.(x|y|theta)/ {printf "%s ", $2}' "$problem")
goal=$(awk -F' *= *' '/^goal\.(x|y|theta)/ {printf "%s ", $2}' "$problem")
echo
echo "== freespace build --cfg $problem"
build/bin/freespace build --cfg "$problem"
echo
echo "== freespace locate --cfg $problem: the start and the goal (one free cell: the keyhole is passable)"
batch=$(mktemp)
trap 'rm -f "$batch"' EXIT
printf '%s\n%s\n' "$start" "$goal" > "$batch"
build/bin/freespace locate --cfg "$problem" --batch "$batch"
