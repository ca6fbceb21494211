#!/usr/bin/env bash
# Translucent-particle benchmark: vtkTransparentSphereMapper (emission-absorption glyphs, GPU depth
# sort, front-to-back compositing; early termination off and on) against what ParaView gives today
# for translucent particles -- vtkOpenGLSphereMapper and the Point Gaussian representation
# composited by dual depth peeling (4 peels) -- in the same process, window and context, on the same
# data and camera path, with the same actor opacity. Data is generated into a temporary directory,
# never committed.
#   1. frame times and per-stage times: random gas (make_particles --kind gas --seed 1, radii
#      0.3-0.5), opacity 0.5, 1e3 ... 1e6 particles, 1024x768, FRAMES orbiting frames (FRAMES_1E6
#      at 1e6) and STATIC_FRAMES frames at rest; two runs per count, mappers in opposite orders
#   2. errors against vtkParticleReferenceRenderer: the same gas without the particles that
#      intersect an earlier one, 1e3 ... 1e5, 512x384; the peers also with 200 peels (converged)
#   3. early termination: clustered data (make_particles --kind clustered --seed 1), opacity 0.9
#      and 0.1, 1e4 ... 1e6, early termination off vs on (20 chunks), twice each (off, on, on, off)
#   4. plots, fits (time = a N^b per stage) and the README tables (plot_transparent.py)
#
# usage: Benchmarks/run_transparent.sh [build-dir]   (needs the project built; runs under Xvfb)
# env: RESULTS_DIR (default Benchmarks/results), FRAMES (10), FRAMES_1E6 (5), STATIC_FRAMES (5)
# writes $RESULTS_DIR/transparent_{timing,errors,early_termination,fits}.csv (replaced) and
# transparent_{time,stages,early_termination}.png, and prints the tables of Benchmarks/README.md
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-${BUILD_DIR:-$top/build}}
results=${RESULTS_DIR:-$top/Benchmarks/results}
frames=${FRAMES:-10}
frames_1e6=${FRAMES_1E6:-5}
static_frames=${STATIC_FRAMES:-5}
mkdir -p "$results"
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
timing="$results/transparent_timing.csv"
errors="$results/transparent_errors.csv"
early="$results/transparent_early_termination.csv"
rm -f "$timing" "$errors" "$early"
start=$(date +%s)

bench() {
  "$top/Scripts/with_xvfb.sh" "$build/bin/prTransparentBenchmark" "$@" |
    grep -v '^ *GL_\|^ *$\|Extensions\|OpenGL\|Visual' || true
}
make_data() { # kind count
  /usr/bin/python3 "$top/Benchmarks/make_particles.py" --kind "$1" --count "$2" --seed 1 \
    --out "$data/$1_$2.vtp" >/dev/null
}

# 1 + 2: mappers, stages, errors (gas, opacity 0.5)
for count in 1000 10000 100000 1000000; do
  make_data gas "$count"
  n=$frames
  [ "$count" -ge 1000000 ] && n=$frames_1e6
  # twice, the mappers in opposite orders, against drifts of the shared machine's load
  for order in "vtksphere-ddp pointgaussian transparent transparent-et" \
    "transparent-et transparent pointgaussian vtksphere-ddp"; do
    mappers=()
    for m in $order; do mappers+=(--mapper "$m"); done
    bench --data "$data/gas_$count.vtp" "${mappers[@]}" --frames "$n" \
      --static-frames "$static_frames" --size 1024x768 --opacity 0.5 --label gas --csv "$timing"
  done
  if [ "$count" -le 100000 ]; then
    bench --data "$data/gas_$count.vtp" --mapper transparent --mapper transparent-et \
      --mapper vtksphere-ddp --mapper pointgaussian --size 512x384 --opacity 0.5 \
      --drop-intersecting --label gas --errors "$errors"
  fi
  if [ "$count" -eq 10000 ]; then # what the intersecting spheres cost the transparent mapper
    bench --data "$data/gas_$count.vtp" --mapper transparent --size 512x384 --opacity 0.5 \
      --label gas-intersecting --errors "$errors"
  fi
  rm -f "$data/gas_$count.vtp"
done

# 3: early termination (clustered, nearly opaque and very transparent)
for count in 10000 100000 1000000; do
  make_data clustered "$count"
  n=$frames
  [ "$count" -ge 1000000 ] && n=$frames_1e6
  for opacity in 0.9 0.1; do
    # off, on, on, off: twice each, in both orders, against drifts of the shared machine's load
    bench --data "$data/clustered_$count.vtp" --mapper transparent --mapper transparent-et \
      --mapper transparent-et --mapper transparent --frames "$n" --static-frames "$static_frames" --size 1024x768 --opacity "$opacity" \
      --label clustered --csv "$early"
  done
  rm -f "$data/clustered_$count.vtp"
done

# 4: plots, fits, tables
/usr/bin/python3 "$top/Benchmarks/plot_transparent.py" --results "$results"
echo "wrote $timing, $errors, $early and the plots in $results ($(($(date +%s) - start)) s)"
