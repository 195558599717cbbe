#!/usr/bin/env bash
# Installs the Debian packages the project builds and runs with.
# Idempotent: does nothing (and needs no network) when every package is present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config clang libclang-rt-14-dev
  libompl-dev ompl-demos
  libfcl-dev libccd-dev
  libeigen3-dev
  libboost-dev libboost-serialization-dev libboost-graph-dev libboost-program-options-dev
  libcgal-dev
  libassimp-dev libpugixml-dev libxxhash-dev
  libgmp-dev libmpfr-dev libmpfi-dev
  libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev librapidcheck-dev
  libtbb-dev
  libmimalloc-dev
  python3-matplotlib
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
