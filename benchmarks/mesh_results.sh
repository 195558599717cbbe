#!/usr/bin/env bash
# Prints the "Real-world meshes" tables of RESULTS.md: what repair and solid
# interpretation cost (bench_mesh_preparation), and how meshes read from the
# generator's soups agree with the exact collision test (bench_locate) and with FCL on
# the files' own triangles (bench_fcl_agreement). Extra arguments are further .cfg
# problems for the FCL table (such as OMPL.app's, which the project does not ship).
#
# Usage: benchmarks/mesh_results.sh BUILD_DIR [PROBLEM.cfg ...]
# (the problems also get a status table: loading, start and goal, build, .path file)
set -euo pipefail
build=${1:?usage: benchmarks/mesh_results.sh BUILD_DIR [PROBLEM.cfg ...]}
shift
scenes=$(mktemp -d)
trap 'rm -rf "$scenes"' EXIT
"$build/bin/freespace" generate --out "$scenes" --scene soup_maze --scene soup_pieces --format dae > /dev/null

echo "Command: \`benchmarks/mesh_results.sh build\`; machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1); $(date +%Y-%m-%d)."
echo
echo "| mesh | triangles | checks only (Mesh::fromSoup) ms | repaired and interpreted (prepareMesh) ms |"
echo "| --- | --- | --- | --- |"
# Closed meshes: medians of 10 interleaved repetitions (the two differ by a few per
# cent, less than the machine drifts between runs); soups once each.
{
  "$build/bin/bench_mesh_preparation" --benchmark_filter=Closed --benchmark_repetitions=10 \
    --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true --benchmark_format=csv
  "$build/bin/bench_mesh_preparation" --benchmark_filter=Soup --benchmark_format=csv
} 2> /dev/null |
  awk -F, '$1 ~ /^"BM_/ && ($1 ~ /Soup/ || $1 ~ /_median"$/) {
    gsub(/"/, "", $1); sub(/_median$/, "", $1); split($1, part, "/"); name = part[1]; arg = part[2];
    ms = $3; triangles = $11;
    if (name ~ /ChecksOnly/) { checks["floor plan " arg " rooms"] = ms; count["floor plan " arg " rooms"] = triangles }
    else if (name ~ /ClosedFloorPlanPrepared/) { prepared["floor plan " arg " rooms"] = ms }
    else { prepared["soup_maze_" arg] = ms; count["soup_maze_" arg] = triangles; checks["soup_maze_" arg] = "refused" }
  } END { for (mesh in count) printf "| %s | %d | %s | %.1f |\n", mesh, count[mesh], checks[mesh] == "refused" ? "refused (not a closed surface)" : sprintf("%.1f", checks[mesh]), prepared[mesh] }' |
  sort
echo
echo "| problem | configurations | disagreements of locate with the exact collision test |"
echo "| --- | --- | --- |"
"$build/bin/bench_locate" "$scenes/soup_maze.cfg" "$scenes/soup_pieces.cfg" 2> /dev/null |
  sed -n 's/^\([a-z_]*\):.*; \([0-9]*\) configurations.*collision test: \([0-9]*\);.*/| \1 | \2 | \3 |/p'
echo
echo "| problem | states | near contact | agree | robot inside an enclosed region | changed by the repair | disagreements |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for cfg in "$scenes/soup_maze.cfg" "$scenes/soup_pieces.cfg" "$@"; do
  "$build/bin/bench_fcl_agreement" "$cfg" 2> /dev/null || true  # problems that do not load are in the status table
done |
  sed -n 's/^\([A-Za-z_]*\): \([0-9]*\) states, \([0-9]*\) near contact skipped, \([0-9]*\) agree, \([0-9]*\) with the robot inside[^)]*), \([0-9]*\) where the repair[^)]*), \([0-9]*\) disagreements$/| \1 | \2 | \3 | \4 | \5 | \6 | \7 |/p'

# The status of each given problem, as a new user meets it: loading with default
# settings, start and goal by the exact test, the construction, and every waypoint of
# the problem's .path file (NAME.path, or PREFIX_planar.path for NAME = PREFIX_variant).
[ $# -gt 0 ] || exit 0
echo
echo "| problem | loads (\`info --cfg\`) | start, goal (exact) | build (\`build --cfg\`) | \`.path\` waypoints in the start's cell |"
echo "| --- | --- | --- | --- | --- |"
for cfg in "$@"; do
  name=$(basename "$cfg" .cfg)
  folder=$(dirname "$cfg")
  state() { sed -n "s/^$1\.$2 *= *//p" "$cfg" | tr -d '\r'; }
  if ! loaded=$("$build/bin/freespace" info --cfg "$cfg" 2>&1 > /dev/null); then
    echo "| $name | no: $(echo "$loaded" | sed -n 's/^error: [^:]*: //p' | cut -d';' -f1) | - | - | - |"
    continue
  fi
  ends=""
  for end in start goal; do
    answer=$("$build/bin/freespace" check --cfg "$cfg" --at "$(state $end x)" "$(state $end y)" "$(state $end theta)" 2> /dev/null)
    ends="$ends${ends:+, }$(echo "$answer" | sed -n 's/.*: exact \([a-z]*\),.*/\1/p')"
  done
  space="$scenes/$name.space"
  built=$("$build/bin/freespace" build --cfg "$cfg" --json --save "$space" 2> /dev/null) || {
    echo "| $name | yes | $ends | refused | - |"
    continue
  }
  seconds=$(echo "$built" | sed -n 's/^  "seconds": \([0-9.]*\),/\1/p')
  cells=$(echo "$built" | sed -n 's/^  "free_cells": \([0-9]*\),/\1/p')
  path="$folder/$name.path"
  [ -f "$path" ] || path="$folder/${name%_*}_planar.path"
  waypoints="-"
  if [ -f "$path" ]; then
    start=$("$build/bin/freespace" locate "$space" --at "$(state start x)" "$(state start y)" "$(state start theta)" 2> /dev/null | sed -n 's/.*free, cell \([0-9]*\).*/\1/p')
    answers=$("$build/bin/freespace" locate "$space" --batch "$path" 2> /dev/null)
    waypoints="$(echo "$answers" | grep -c "free, cell $start\(,.*\)\?\$") of $(echo "$answers" | grep -c .) ($(basename "$path"))"
  fi
  printf '| %s | yes | %s | %.2f s, %s free cells | %s |\n' "$name" "$ends" "$seconds" "$cells" "$waypoints"
done
