#!/usr/bin/env bash
# Prints the "Maximum clearance paths" table of RESULTS.md: `freespace plan --json` on
# every bundled problem (or the .cfg problems given), with a time limit per query, three
# times each: the row of the run whose query time is the median, with the least and the
# most (the machine's speed drifts from run to run).
#
# Usage: benchmarks/plan_results.sh BUILD_DIR SECONDS_LIMIT [PROBLEM.cfg ...]
set -euo pipefail
build=${1:?usage: benchmarks/plan_results.sh BUILD_DIR SECONDS_LIMIT [PROBLEM.cfg ...]}
limit=${2:?usage: benchmarks/plan_results.sh BUILD_DIR SECONDS_LIMIT [PROBLEM.cfg ...]}
shift 2
problems=("$@")
given="${*:+ $*}"  # the problems as given, for the command line printed
if [ ${#problems[@]} -eq 0 ]; then problems=("$(dirname "$0")"/problems/*.cfg); fi

echo "Command: \`benchmarks/plan_results.sh build $limit$given\`; machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1); $(date +%Y-%m-%d)."
echo
echo "| problem | status | converged | c_lo (path) | c_hi (any path) | c_lo / c_hi | waypoints | first path s | query s, median (least-most) | construction s | boxes |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
# One table row from one plan's JSON.
read -r -d '' row << 'PYTHON' || true
import json, sys
name = sys.argv[1]
runs = sorted((json.loads(line) for line in sys.stdin), key=lambda run: run["seconds"]["query"])
plan = runs[len(runs) // 2]
s = plan["seconds"]
spread = f"{s['query']:.2f} ({runs[0]['seconds']['query']:.2f}-{runs[-1]['seconds']['query']:.2f})"
if plan["status"] == "infeasible":
    print(f"| {name} | infeasible ({plan['proof']}) | - | - | - | - | - | - | {s['query']:.4f} | {s['construction']:.3f} | - |")
else:
    lo, hi = plan["clearance_lower"], plan["clearance_upper"]
    found = lo is not None and lo > 0
    ratio = f"{lo / hi:.4f}" if found and hi else "-"
    lo_text = f"{lo:.6g}" if found else "none"
    waypoints = len(plan.get("waypoints", [])) or "-"
    converged = "yes" if plan["converged"] else "no"
    print(f"| {name} | {plan['status']} | {converged} | {lo_text} | {hi:.6g} | {ratio} | {waypoints} | {s['first_path']:.3f} | {spread} | {s['construction']:.3f} | {plan['boxes']} |")
PYTHON
for cfg in "${problems[@]}"; do
  for _ in 1 2 3; do
    "$build/bin/freespace" plan --json --cfg "$cfg" --seconds-limit "$limit" 2> /dev/null | python3 -c 'import json, sys; print(json.dumps(json.load(sys.stdin)))'
  done | python3 -c "$row" "$(basename "$cfg" .cfg)"
done
