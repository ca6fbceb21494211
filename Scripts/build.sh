#!/usr/bin/env bash
# Configures and builds ParticleRendering into ${BUILD_DIR:-build} (Release, shared libraries).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$top/build}
cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)"
echo "build: plugin at $build/lib/paraview-plugins/ParticleRendering/ParticleRendering.so"
