#!/usr/bin/env bash
# Prints the "Saving and loading a free space" table of RESULTS.md: for generated
# floor plans, whole `freespace` processes (/usr/bin/time): `build --cfg` (the
# construction and the cell graph), `build --cfg --save`, and `locate` from the saved
# file (the load and one query). Builds: median of 3; loads: median of 5.
#
# Usage: benchmarks/persistence_results.sh BUILD_DIR [SCENE ...]
# (default scenes: tetra_floorplan_1024 and house_mixed_160, the 8,700-facet floor
# plan against the 14-facet house robot)
set -euo pipefail
build=${1:?usage: benchmarks/persistence_results.sh BUILD_DIR [SCENE ...]}
shift
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then scenes=(tetra_floorplan_1024 house_mixed_160); fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
freespace="$build/bin/freespace"

# "seconds peak_kilobytes" of one run of the command.
measured() {
  /usr/bin/time -f "%e %M" -o "$work/time" "$@" > /dev/null 2> "$work/stderr" ||
    { cat "$work/stderr" >&2; exit 1; }
  cat "$work/time"
}

# The median of the first column of the lines on stdin, and its line's second column.
median() { sort -n | awk '{ line[NR] = $0 } END { print line[int((NR + 1) / 2)] }'; }

echo "Command: \`benchmarks/persistence_results.sh build ${scenes[*]}\`; machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1); $(date +%Y-%m-%d)."
echo
echo "| scene | robot / world facets | build s | peak GB (build) | build + save s | file MB | load + locate s | peak GB (load) | build / load |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
  facets=$("$freespace" generate --out "$work" --scene "$scene" --force | sed -n 's/.*robot \([0-9]*\) triangles, world \([0-9]*\) triangles.*/\1 \/ \2/p')
  cfg="$work/$scene.cfg"
  read -r build_s build_kb < <(for _ in 1 2 3; do measured "$freespace" build --cfg "$cfg"; done | median)
  read -r save_s _ < <(measured "$freespace" build --cfg "$cfg" --save "$work/$scene.fspace")
  file_mb=$(($(stat -c %s "$work/$scene.fspace") / 1000000))
  read -r load_s load_kb < <(for _ in 1 2 3 4 5; do measured "$freespace" locate "$work/$scene.fspace" --at 1.5 1.5 0; done | median)
  awk -v scene="$scene" -v facets="$facets" -v b="$build_s" -v bk="$build_kb" -v s="$save_s" -v mb="$file_mb" \
    -v l="$load_s" -v lk="$load_kb" 'BEGIN {
      printf "| %s | %s | %.2f | %.2f | %.2f | %d | %.2f | %.2f | %.1f |\n", scene, facets, b, bk / 1048576, s, mb, l, lk / 1048576, b / l }'
  rm -f "$work/$scene.fspace"
done
