#!/usr/bin/env bash
# Ambient-occlusion benchmarks of vtkDensityVolumeAOPass (Grottel et al. 2012):
#   1. ao_study.py: error against ray-traced AO vs frame time for the quality knobs (splat,
#      resolution, fetch distance) with vtkSSAOPass on the same chart, and the FCC lattice
#      artefact (paper Fig. 6)  -> ao_accuracy.{csv,png}, ao_fcc_artefact.png
#   2. prAOBenchmark: the paper's Table 1 -- frame time with AO over frame time without, 1e4 ... 1e6
#      particles, static scene and time series (volume rebuilt every frame), CPU vs GPU generation
#      -> ao_timing.csv, ao_overhead.png
# usage: Benchmarks/run_ao.sh [build-dir]   (needs the project built; runs under Xvfb)
# env: RESULTS_DIR (default Benchmarks/results), SAMPLES (reference rays per pixel, 256)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-${BUILD_DIR:-$top/build}}
results=${RESULTS_DIR:-$top/Benchmarks/results}
mkdir -p "$results"
export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
"$top/Scripts/with_xvfb.sh" /usr/bin/python3 "$top/Benchmarks/ao_study.py" \
  --data "$top/Testing/Data" --out "$results" --samples "${SAMPLES:-256}" --frames 9
"$top/Scripts/with_xvfb.sh" /usr/bin/python3 "$top/Benchmarks/ao_benchmark.py" \
  --out "$results" --counts "${COUNTS:-1e4,1e5,1e6}" --frames "${FRAMES:-9}"
