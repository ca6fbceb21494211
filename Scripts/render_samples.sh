#!/usr/bin/env bash
# README command 1: install what is needed, build, then render every technique on the bundled
# LAMMPS data through pvpython with the plugin (Scripts/render_samples.py): one PNG per picture,
# a labelled contact sheet, and a table (CSV + Markdown) of each picture's frame time over the
# opaque core and its error against the reference renderer, all measured in the same run.
#   bash Scripts/render_samples.sh [--quick | --full] [--no-build] [render_samples.py options]
# --quick: small pictures, one timed frame (the CTest smoke test); --full: 640x480, more frames
# and reference rays; --no-build: skip install_dependencies.sh and build.sh (a built tree).
# Output: ${OUT_DIR:-out/samples}; build tree: ${BUILD_DIR:-build} (PLUGIN and PVPYTHON override
# the plugin and pvpython found there and on PATH).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build_first=1
args=()
for a in "$@"; do
  if [ "$a" = --no-build ]; then build_first=0; else args+=("$a"); fi
done
if [ "$build_first" = 1 ]; then
  "$top/Scripts/install_dependencies.sh"
  "$top/Scripts/build.sh"
fi
build=${BUILD_DIR:-$top/build}
out=${OUT_DIR:-$top/out/samples}
plugin=${PLUGIN:-$build/lib/paraview-plugins/ParticleRendering/ParticleRendering.so}
[ -e "$plugin" ] || { echo "render_samples: no plugin at $plugin (build first: bash Scripts/build.sh)" >&2; exit 1; }
mkdir -p "$out"
# the reference renderer is in the build's Python package (particlerendering)
export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
"$top/Scripts/with_xvfb.sh" "${PVPYTHON:-pvpython}" --force-offscreen-rendering "$top/Scripts/render_samples.py" \
  --plugin "$plugin" --data "$top/Testing/Data" --out "$out" ${args[@]+"${args[@]}"}
