#!/usr/bin/env bash
# First benchmark table: the sphere imposter core (vtkParticleSphereMapper, with and without
# occlusion culling) against vtkPointGaussianMapper (ParaView's "Sphere" splat, the peer) and VTK's
# vtkOpenGLSphereMapper, drawn in the same process on the same data and camera path, 1024x768.
# Data (random gas with vertex cells) is generated into a temporary directory, never committed.
#
# usage: [LARGE=1] Benchmarks/run_sphere_core.sh [build-dir]   (needs the project built; runs under Xvfb)
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
# Scenes: the sparse random gas (number density 0.1) and the dense lattice (touching spheres) at
# 10^4..10^6, and the LAMMPS liquid film of the tests (19 360 atoms). Peer: Point Gaussian.
run() { # label file
  "$top/Scripts/with_xvfb.sh" "$build/bin/prBenchmark" --data "$2" \
    --mapper pointgaussian --mapper vtksphere --mapper particle-nocull --mapper particle \
    --frames "${FRAMES:-10}" --size 1024x768 --label "$1" --csv "$csv" \
    --screenshot "$data" | grep -v '^ *GL_\|^ *$\|Extensions\|OpenGL\|Visual'
}
for kind in gas lattice; do
  for count in 10000 100000 1000000; do
    /usr/bin/python3 "$top/Benchmarks/make_particles.py" --kind "$kind" --count "$count" --seed 1 \
      --out "$data/${kind}_$count.vtp" >/dev/null
    run "$kind" "$data/${kind}_$count.vtp"
  done
done
run lj_film "$top/Testing/Data/lj_film.vtp"
# LARGE=1: also 10^7 gas particles (3 frames; ~80 s, 2 GB of memory, a 430 MB temporary file)
if [ "${LARGE:-0}" = 1 ]; then
  /usr/bin/python3 "$top/Benchmarks/make_particles.py" --kind gas --count 10000000 --seed 1 \
    --out "$data/gas_10000000.vtp" >/dev/null
  "$top/Scripts/with_xvfb.sh" "$build/bin/prBenchmark" --data "$data/gas_10000000.vtp" \
    --mapper pointgaussian --mapper particle-nocull --mapper particle \
    --frames 3 --size 1024x768 --label gas --csv "$csv" | grep -v '^ *GL_\|^ *$\|Extensions\|OpenGL\|Visual'
fi
/usr/bin/python3 "$top/Benchmarks/plot_results.py" "$csv" "$results/sphere_core.png" \
  --title "Sphere core vs Point Gaussian and vtkOpenGLSphereMapper (1024x768, llvmpipe)"
echo "wrote $csv and $results/sphere_core.png"
