#!/usr/bin/env bash
# Installs the built project into a scratch prefix, builds examples/consumer against
# it with find_package(freespace), and runs it on two meshes: one configuration must
# be free and one in collision.
set -euo pipefail
build_dir=$1
source_dir=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build_dir" --prefix "$scratch/prefix" >/dev/null
cmake -S "$source_dir/examples/consumer" -B "$scratch/build" -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
cmake --build "$scratch/build" >/dev/null
robot=$source_dir/tests/data/meshes/cube.obj
world=$source_dir/tests/data/meshes/cube.obj
free=$("$scratch/build/consumer" "$robot" "$world" 10 0 0)
hit=$("$scratch/build/consumer" "$robot" "$world" 0.25 0.25 0.5)
echo "at (10, 0, 0): $free; at (0.25, 0.25, 0.5): $hit"
[ "$free" = free ] && [ "$hit" = collision ]
