#!/usr/bin/env bash
# README command 1: install what is needed, build, and render the bundled LAMMPS sample data
# with the Particles representation into PNGs (their paths are printed at the end).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/Scripts/install_dependencies.sh"
"$top/Scripts/build.sh"
build=${BUILD_DIR:-$top/build}
out=${OUT_DIR:-$top/out/samples}
mkdir -p "$out"
"$top/Scripts/with_xvfb.sh" pvpython "$top/Scripts/render_samples.py" \
  --plugin "$build/lib/paraview-plugins/ParticleRendering/ParticleRendering.so" \
  --data "$top/Testing/Data" --out "$out"
