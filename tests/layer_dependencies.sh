#!/usr/bin/env bash
# The robust-number layer (include/freespace/numbers, src/numbers) includes only its
# own headers and arithmetic libraries: no meshes or other project layers, no
# Eigen, OMPL, FCL or assimp.
set -euo pipefail
cd "$1"
violations=$(grep -HnE '#include' include/freespace/numbers/* src/numbers/* |
  grep -E '#include [<"](freespace/(geometry|io|collision|problem|scenes|planning)|Eigen|ompl|fcl|assimp)' || true)
files=$(ls include/freespace/numbers/* src/numbers/* | wc -l)
if [ -n "$violations" ]; then
  echo "the number layer depends on other layers or libraries:"
  echo "$violations"
  exit 1
fi
echo "number layer: $files files, no dependency on meshes, OMPL, FCL, Eigen or assimp"
