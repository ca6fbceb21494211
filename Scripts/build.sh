#!/usr/bin/env bash
# Configures and builds ParticleRendering into ${BUILD_DIR:-build} (Release, shared libraries);
# ${PR_CMAKE_ARGS} (words) go to the configure step, e.g. -DPARTICLERENDERING_DEPRECATION_ERRORS=ON.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$top/build}
# shellcheck disable=SC2086
cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release ${PR_CMAKE_ARGS:-}
cmake --build "$build" -j "$(nproc)"
echo "build: plugin at $build/lib/paraview-plugins/ParticleRendering/ParticleRendering.so"
