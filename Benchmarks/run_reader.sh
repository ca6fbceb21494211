#!/usr/bin/env bash
# Speed and memory of vtkLAMMPSDumpReader against numpy.loadtxt and ParaView's CSV reader on a
# 10^7-atom LAMMPS dump (written by lmp on first use, ~600 MB, in $WORK).
#   -> reader_speed.{csv,png}
# usage: Benchmarks/run_reader.sh [build-dir]   (needs the project built; ~2 min)
# env: RESULTS_DIR (default Benchmarks/results), ATOMS (1e7), WORK (/tmp/reader_benchmark)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-${BUILD_DIR:-$top/build}}
results=${RESULTS_DIR:-$top/Benchmarks/results}
export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
/usr/bin/python3 "$top/Benchmarks/reader_benchmark.py" --out "$results" \
  --atoms "${ATOMS:-1e7}" --work "${WORK:-/tmp/reader_benchmark}"
