#!/usr/bin/env bash
# Strong scaling of distributed rendering (Benchmarks/mpi_scaling.py): 1, 2 and 4 ranks for the
# LAMMPS film repeated 2x2 (77 440 atoms) and 7x7 (948 640 atoms) at 800x600, one X display for
# all ranks. The machine has 2 cores: 4 ranks oversubscribe it. Appends to
# Benchmarks/results/mpi_scaling.csv and draws mpi_scaling.png.
# usage: Benchmarks/run_mpi_scaling.sh [BUILD_DIR]
# env: RESULTS_DIR (default Benchmarks/results), BUILD_DIR (when no argument; default build),
#      REPEATS (the film's repeats, default "2 7"; 23: 10 240 640 atoms, about 10^7),
#      FRAMES (frames per mean, default 5)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-${BUILD_DIR:-$top/build}}
results=${RESULTS_DIR:-$top/Benchmarks/results}
mkdir -p "$results"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export PYTHONPATH="$build/lib/python3/dist-packages"
for repeat in ${REPEATS:-2 7}; do
  for np in 1 2 4; do
    "$top/Scripts/with_xvfb.sh" mpiexec -np "$np" --oversubscribe -x DISPLAY -x PYTHONPATH \
      pvbatch "$top/Benchmarks/mpi_scaling.py" \
      --plugin "$build/lib/paraview-plugins/ParticleRendering/ParticleRendering.so" \
      --data "$top/Testing/Data" --repeat "$repeat" --frames "${FRAMES:-5}" --csv "$results/mpi_scaling.csv"
  done
done
/usr/bin/python3 "$top/Benchmarks/plot_mpi_scaling.py" "$results/mpi_scaling.csv" "$results/mpi_scaling.png"
