#!/usr/bin/env bash
# Installs the Debian bookworm packages the project needs, and any package named on the command line
# (scripts/fuzz.sh adds clang's), when one is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config python3
  libompl-dev libfcl-dev libccd-dev libeigen3-dev liburdfdom-dev libtinyxml2-dev
  libboost-program-options-dev libboost-serialization-dev libboost-filesystem-dev libboost-system-dev
  libode-dev libassimp-dev libgtest-dev librsvg2-bin doxygen
  ompl-demos parallel python3-matplotlib libjs-three chromium liborocos-kdl-dev
  python3-dev pybind11-dev python3-numpy python3-pytest python3-pandas
  slurm-wlm munge sqlite3
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
