#!/usr/bin/env bash
# Configures and builds the project into build/ (Release, the libraries' sources compiled in batches:
# OMPL_MM_UNITY_BUILD; more CMake options may follow, -DOMPL_MM_UNITY_BUILD=OFF for quicker
# rebuilds of one changed file).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DOMPL_MM_UNITY_BUILD=ON "$@" > /dev/null
cmake --build build -j "$jobs"
