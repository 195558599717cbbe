#!/usr/bin/env bash
# Prints the "Real-world meshes" tables of RESULTS.md: what repair and solid
# interpretation cost (bench_mesh_preparation), and how meshes read from the
# generator's soups agree with the exact collision test (bench_locate) and with FCL on
# the files' own triangles (bench_fcl_agreement). Extra arguments are further .cfg
# problems for the FCL table (such as OMPL.app's, which the project does not ship).
#
# Usage: benchmarks/mesh_results.sh BUILD_DIR [PROBLEM.cfg ...]
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
"$build/bin/bench_mesh_preparation" --benchmark_format=csv 2> /dev/null |
  awk -F, 'NR > 1 {
    gsub(/"/, "", $1); split($1, part, "/"); name = part[1]; arg = part[2];
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
"$build/bin/bench_fcl_agreement" "$scenes/soup_maze.cfg" "$scenes/soup_pieces.cfg" "$@" 2> /dev/null |
  sed -n 's/^\([A-Za-z_]*\): \([0-9]*\) states, \([0-9]*\) near contact skipped, \([0-9]*\) agree, \([0-9]*\) with[^,]*, \([0-9]*\) where.*, \([0-9]*\) disagreements$/| \1 | \2 | \3 | \4 | \5 | \6 | \7 |/p'
