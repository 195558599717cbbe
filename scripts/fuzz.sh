#!/usr/bin/env bash
# Builds the readers' libFuzzer targets (tests/fuzz) with clang and runs each for a
# bounded time, seeded from the project's own files (tests/data, benchmarks/problems,
# meshes the generator writes; those under 64 kB, so that runs stay quick) and the
# inputs earlier runs found
# (tests/fuzz/regressions/TARGET). Exits non-zero at the first crash, sanitizer error,
# hang (10 s per input) or runaway memory (an allocation of 2 GB, or 8 GB in all),
# keeping the input in the work folder. Leaks are not counted: assimp 5.2 leaks 1 to
# 2 kB on some malformed COLLADA and STL files, which the project cannot mend, and over
# a long run they add up (2 GB after 240,000 STL inputs).
#
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET] [WORK_FOLDER]   (default 30, a temporary
# folder removed after a run without failure); needs the project built (scripts/build.sh).
# FUZZ_SEED (default 1) seeds libFuzzer's choices: with the same seed, corpus and
# machine a shorter run repeats the start of a longer one, so the test suite's short
# run is known to pass; another seed explores further.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
if [ -n "${2:-}" ]; then
  work=$(realpath -m "$2")
else
  work=$(mktemp -d)
  keepWork=no
fi
mkdir -p "$work"
# The targets' input files, in memory where there is /dev/shm; removed on any exit.
export FREESPACE_FUZZ_FILES
FREESPACE_FUZZ_FILES=$(mktemp -d -p "$( [ -w /dev/shm ] && echo /dev/shm || echo /tmp )" freespace-fuzz.XXXXXX)
trap 'rm -rf "$FREESPACE_FUZZ_FILES"' EXIT
cmake -S tests/fuzz -B "$work/build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DFREESPACE_BUILD_DIR="$PWD/build" > "$work/configure.log"
cmake --build "$work/build" -j"$(nproc)" > "$work/build.log"

# Seeds: the project's own files of each kind, and meshes of every format from the generator.
generated="$work/generated"
if [ ! -d "$generated" ]; then
  for format in obj stl ply off dae vtk; do
    build/bin/freespace generate --out "$generated/$format" --scene keyhole --scene soup_pieces --format "$format" > /dev/null
  done
  # The COLLADA writer stamps the time: one date, so that every run starts from the same seeds.
  find "$generated/dae" -name "*.dae" -exec sed -i -e 's#<created>[^<]*</created>#<created>2026-01-01T00:00:00</created>#' \
    -e 's#<modified>[^<]*</modified>#<modified>2026-01-01T00:00:00</modified>#' {} +
fi
# The payloads of small saved free spaces (the saved-space target adds header and checksum).
savedSpacePayloads() {
  local folder="$work/saved" cube=tests/data/meshes/cube.obj
  if [ ! -d "$folder" ]; then
    mkdir -p "$folder"
    build/bin/freespace build "$cube" "$cube" --save "$folder/cube.fspace" > /dev/null
    # The payload follows the header line; its 8-byte length and 8-byte checksum follow it.
    tail -c +$(( $(head -n 1 "$folder/cube.fspace" | wc -c) + 1 )) "$folder/cube.fspace" | head -c -16 > "$folder/cube.payload"
  fi
  echo "$folder/cube.payload"
}
seeds() {  # TARGET -> folder of seed files (paths from the project's root)
  local target=$1 folder="$work/seeds/$1" extension=${1#fuzz_mesh_} i=0
  mkdir -p "$folder"
  case $target in
    fuzz_cfg) files=$(find benchmarks/problems "$generated/obj" -name "*.cfg") ;;
    fuzz_path) files=$(find benchmarks -name "*.path") ;;
    fuzz_saved_space) files=$(savedSpacePayloads) ;;
    *) files=$(find tests/data benchmarks/problems "$generated/$extension" -name "*.$extension" -size -64k) ;;
  esac
  [ -d "tests/fuzz/regressions/$target" ] && files="$files $(find "tests/fuzz/regressions/$target" -type f)"
  for file in $files; do cp "$file" "$folder/$((i++))_$(basename "$file")"; done
  printf '0 0 0\n1.5 -2 3.1 # a comment\n\n# only a comment\n' > "$folder/batch.path"
  echo "$folder"
}

for binary in "$work"/build/fuzz_*; do
  target=$(basename "$binary")
  corpus="$work/corpus/$target"
  mkdir -p "$corpus" "$work/findings/$target"
  echo "fuzz: $target for $seconds s"
  seedFolder=$(seeds "$target")
  (cd "$work/findings/$target" && ASAN_OPTIONS=detect_leaks=0 "$binary" -max_total_time="$seconds" -timeout=10 -malloc_limit_mb=2048 -rss_limit_mb=8192 \
    -detect_leaks=0 -seed="${FUZZ_SEED:-1}" -print_final_stats=1 "$corpus" "$seedFolder" > "$work/$target.log" 2>&1) || {
    echo "fuzz: $target found a failure; its input is in $work/findings/$target:"
    grep -E "ERROR|SUMMARY|Test unit written" "$work/$target.log" | head -5
    exit 1
  }
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$work/$target.log" | tr '\n' ' '
  echo
done
echo "fuzz: no failure in $(ls "$work"/build/fuzz_* | wc -l) targets"
if [ "${keepWork:-yes}" = no ]; then rm -rf "$work"; fi
