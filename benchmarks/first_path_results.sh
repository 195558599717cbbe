#!/usr/bin/env bash
# Prints the "First path" table of RESULTS.md: the milliseconds `freespace plan --json`
# takes to its first certified path (after construction and graph), RUNS runs per solvable
# bundled problem (or per .cfg problem given): their median, least and most. The
# queries ask for a ratio of 0.5 (the first path does not depend on it) to end soon.
#
# Usage: benchmarks/first_path_results.sh BUILD_DIR RUNS [PROBLEM.cfg ...]
set -euo pipefail
build=${1:?usage: benchmarks/first_path_results.sh BUILD_DIR RUNS [PROBLEM.cfg ...]}
runs=${2:?usage: benchmarks/first_path_results.sh BUILD_DIR RUNS [PROBLEM.cfg ...]}
shift 2
problems=("$@")
given="${*:+ $*}"  # the problems as given, for the command line printed
if [ ${#problems[@]} -eq 0 ]; then problems=("$(dirname "$0")"/problems/*.cfg); fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "Command: \`benchmarks/first_path_results.sh build $runs$given\`; machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1); $(date +%Y-%m-%d)."
echo
echo "| problem | first path ms, median | least | most |"
echo "| --- | --- | --- | --- |"
# One table row from the runs' JSON files.
read -r -d '' row << 'PYTHON' || true
import glob, json, sys
name, files = sys.argv[1], sorted(glob.glob(sys.argv[2] + "/*.json"))
plans = [json.load(open(f)) for f in files]
if all(p["status"] == "infeasible" for p in plans):
    sys.exit(0)
solved = [p for p in plans if p["status"] == "solved"]
if len(solved) < len(plans):
    print(f"| {name} | {len(plans) - len(solved)} of {len(plans)} runs not solved | - | - |")
    sys.exit(0)
ms = sorted(p["seconds"]["first_path"] * 1e3 for p in solved)
print(f"| {name} | {ms[len(ms) // 2]:.2f} | {ms[0]:.2f} | {ms[-1]:.2f} |")
PYTHON
for cfg in "${problems[@]}"; do
  name=$(basename "$cfg" .cfg)
  rm -f "$work"/*.json
  failed=0
  for run in $(seq "$runs"); do
    "$build/bin/freespace" plan --json --cfg "$cfg" --ratio 0.5 --seconds-limit 2 > "$work/$run.json" 2> "$work/stderr" ||
      failed=$?
  done
  if [ "$failed" -ne 0 ]; then
    echo "| $name | plan failed (exit status $failed: $(head -c 200 "$work/stderr")) | - | - |"
    continue
  fi
  python3 -c "$row" "$name" "$work"
done
