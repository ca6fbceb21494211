#!/usr/bin/env bash
# Distributed rendering against the single-process picture on a gas-plus-slab scene and a
# deeply penetrating scene (Benchmarks/mpi_partition_accuracy.py): np 1, 2 and 3, one X display
# for all ranks. Writes mpi_partition_accuracy.csv and .png to RESULTS_DIR and prints the table.
# usage: Benchmarks/run_mpi_partition_accuracy.sh [BUILD_DIR]
# env: RESULTS_DIR (default Benchmarks/results), IMAGE_DIR (default BUILD_DIR/mpi_partition_accuracy),
#      CASES (a comma-separated subset of the cases, scene:settings:compositing; default all),
#      RESULTS_NAME (default mpi_partition_accuracy; the CSV and PNG names),
#      SIZE (default "400 300"; issue 61's reproducer: "480 360")
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-${BUILD_DIR:-$top/build}}
results=${RESULTS_DIR:-$top/Benchmarks/results}
images=${IMAGE_DIR:-$build/mpi_partition_accuracy}
mkdir -p "$results" "$images"
rm -f "$images"/*_np[0-9].png
cases=()
[ -n "${CASES:-}" ] && cases=(--cases "$CASES")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export PYTHONPATH="$build/lib/python3/dist-packages"
for np in 1 2 3; do
  "$top/Scripts/with_xvfb.sh" mpiexec -np "$np" --oversubscribe -x DISPLAY -x PYTHONPATH \
    pvbatch "$top/Benchmarks/mpi_partition_accuracy.py" \
    --plugin "$build/lib/paraview-plugins/ParticleRendering/ParticleRendering.so" \
    --out "$images" --size ${SIZE:-400 300} "${cases[@]}"
done
/usr/bin/python3 "$top/Benchmarks/mpi_partition_accuracy_compare.py" "$images" \
  "$results/${RESULTS_NAME:-mpi_partition_accuracy}.csv" \
  "$results/${RESULTS_NAME:-mpi_partition_accuracy}.png"
