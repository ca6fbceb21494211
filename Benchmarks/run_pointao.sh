#!/usr/bin/env bash
# PointAO benchmarks (vtkPointAOPass, Eichelbaum et al. 2013):
#   1. pointao_study.py: error against ray-traced AO vs frame time over PointAO's levels and
#      directions, with vtkSSAOPass, the density volume and voxel cones on the same chart; the
#      silhouette band, orbit flicker and 2x window  -> pointao_accuracy.{csv,png}
#   2. pointao_benchmark.py: frame time over the plain core at 1e4 ... 1e6 particles and two
#      window sizes, per-stage GPU times, vtkSSAOPass and the density volume in the same run
#      -> pointao_timing.{csv,png}
# usage: Benchmarks/run_pointao.sh [build-dir]   (needs the project built; runs under Xvfb)
# env: RESULTS_DIR (default Benchmarks/results), SAMPLES (reference rays per pixel, 256)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-${BUILD_DIR:-$top/build}}
results=${RESULTS_DIR:-$top/Benchmarks/results}
mkdir -p "$results"
export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
"$top/Scripts/with_xvfb.sh" /usr/bin/python3 "$top/Benchmarks/pointao_study.py" \
  --data "$top/Testing/Data" --out "$results" --samples "${SAMPLES:-256}" --frames 9
"$top/Scripts/with_xvfb.sh" /usr/bin/python3 "$top/Benchmarks/pointao_benchmark.py" \
  --out "$results" --counts "${COUNTS:-1e4,1e5,1e6}" --sizes "${SIZES:-640x360,1280x720}" \
  --frames "${FRAMES:-9}"
