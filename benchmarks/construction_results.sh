#!/usr/bin/env bash
# Prints the "Construction" tables of RESULTS.md: from bench_construction's lines, the
# tetrahedron in floor plans of 1 to 256 rooms, the 14-facet house in mixed-height
# floor plans of 1 to 160 rooms and robots of 4 to 108 facets in one of 4 rooms (one
# build each, redrawing benchmarks/construction_time.svg), then the construction's
# targets on one core, each the fastest of several builds; from bench_locate's lines,
# every bundled problem's construction and `locate` against the exact collision test
# on 100,000 random configurations.
#
# Usage: benchmarks/construction_results.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: benchmarks/construction_results.sh BUILD_DIR}
bench="$build/bin/bench_construction"
here=$(dirname "$0")

# bench_construction's lines ("NAME robot R, world W facets: S s (...); P patches, ...;
# peak M MB; double intervals D%") as table rows.
rows() {
  perl -ne 'if (/^(\S+) +robot (\d+), world (\d+) facets: ([\d.e-]+) s \([^)]*\); (\d+) patches, (\d+) curves, (\d+) vertices, (\d+) sub-faces, (\d+) shells, (\d+) free cells; peak ([\d.]+) MB; double intervals ([\d.]+%)$/) {
      print "| $1 | $2 / $3 | $4 | $5 | $6 | $7 | $8 | $9 | $10 | $11 | $12 |\n" } else { print STDERR "unread: $_" }'
}

echo "Command: \`benchmarks/construction_results.sh build\`; machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1); $(date +%Y-%m-%d)."
echo
echo "| scene | robot / world facets | seconds | patches | curves | vertices | sub-faces | shells | free cells | process peak MB so far | decided in double intervals |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
"$bench" --rooms 256 --mixed-rooms 160 --robots 4 --plot "$here/construction_time.svg" | rows
echo
echo "Targets, on one core (\`taskset -c 1\`), the fastest of 7 builds (3 for house_mixed_160):"
echo
echo "| scene | robot / world facets | seconds | target s |"
echo "| --- | --- | --- | --- |"
{
  taskset -c 1 "$bench" --rooms 0 --repeat 7 tetra_floorplan_21 tetra_floorplan_76 tetra_floorplan_128
  taskset -c 1 "$bench" --rooms 0 --robots 0 --repeat 3 house_mixed_160
} | rows |
  awk -F' \\| ' 'BEGIN { target["tetra_floorplan_21"] = 0.05; target["tetra_floorplan_76"] = 0.2;
      target["tetra_floorplan_128"] = 0.8; target["house_mixed_160"] = 8 }
    { name = substr($1, 3); printf "| %s | %s | %s | %s |\n", name, $2, $3, target[name] }'
echo
echo "Every bundled problem: \`locate\` against the exact collision test on 100,000 random configurations (bench_locate):"
echo
echo "| problem | robot / world facets | build s | patches | shells | free cells | free configurations | disagreements | locate us | collision test us |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
"$build/bin/bench_locate" | perl -ne 'if (/^(\S+): robot (\d+) triangles, world (\d+) triangles; build ([\d.e-]+) s \(.*, (\d+) patches, (\d+) shells, \d+ free, (\d+) free cells\); (\d+) configurations, (\d+) free, in \d+ cells; disagreements with the exact collision test: (\d+); locate ([\d.e-]+) us, collision test ([\d.e-]+) us per configuration$/) {
    printf "| %s | %s / %s | %.4f | %s | %s | %s | %s | %s | %.2f | %.2f |\n", $1, $2, $3, $4, $5, $6, $7, $9, $10, $11, $12 } else { print STDERR "unread: $_" }'
