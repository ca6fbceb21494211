#!/usr/bin/env bash
# First benchmark table: the sphere imposter core (vtkParticleSphereMapper) against VTK's
# vtkOpenGLSphereMapper and vtkPointGaussianMapper (ParaView's "Sphere" splat), drawn in the same
# process on the same data and camera path, at 1e4, 1e5 and 1e6 particles, 1024x768.
# Data (random gas with vertex cells) is generated into a temporary directory, never committed.
#
# usage: Benchmarks/run_sphere_core.sh [build-dir]   (needs the project built; runs under Xvfb)
# writes Benchmarks/results/sphere_core.csv (replaced) and sphere_core.png (RESULTS_DIR overrides)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-${BUILD_DIR:-$top/build}}
results=${RESULTS_DIR:-$top/Benchmarks/results}
mkdir -p "$results"
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
csv="$results/sphere_core.csv"
rm -f "$csv"
for count in 10000 100000 1000000; do
  /usr/bin/python3 "$top/Benchmarks/make_particles.py" --kind gas --count "$count" --seed 1 \
    --out "$data/gas_$count.vtp"
  "$top/Scripts/with_xvfb.sh" "$build/bin/prBenchmark" --data "$data/gas_$count.vtp" \
    --mapper vtksphere --mapper pointgaussian --mapper particle \
    --frames "${FRAMES:-10}" --size 1024x768 --label gas --csv "$csv" \
    --screenshot "$data" | grep -v '^ *GL_\|^ *$\|Extensions\|OpenGL\|Visual'
done
/usr/bin/python3 "$top/Benchmarks/plot_results.py" "$csv" "$results/sphere_core.png" \
  --title "Sphere core vs VTK peers (random gas, 1024x768, llvmpipe)"
echo "wrote $csv and $results/sphere_core.png"
