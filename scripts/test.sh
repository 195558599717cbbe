#!/usr/bin/env bash
# Sets everything up, builds, and runs the whole test suite, then the readers' fuzz
# targets for 20 s each (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)"
cd ..
bash scripts/fuzz.sh 20
