#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer run: builds ParticleRendering's libraries, the C++
# tests and both reader fuzzers instrumented into ${SANITIZER_BUILD_DIR:-build-sanitizers}
# (-O1 with assertions, no Python wrapping: a sanitized module cannot be loaded into an
# uninstrumented python), then runs the C++ tests and the fuzzers under Xvfb. Any invalid memory
# access (ASan) or undefined behaviour (UBSan: overflow, misaligned or null access, bad shifts,
# invalid enum or bool values, ...) fails the run. Leak checking is off: Mesa's driver is
# unloaded at exit (its allocations leave no symbols to tell them from ours) and VTK 9.2's
# renderer leaks the order-independent translucency pass it creates. Extra arguments go to ctest.
# Needs what Scripts/install_dependencies.sh installs.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${SANITIZER_BUILD_DIR:-$top/build-sanitizers}
"$top/Scripts/install_dependencies.sh"
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g -O1"
start=$(date +%s)
cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_FLAGS_RELEASE="$flags" -DCMAKE_CXX_FLAGS_RELEASE="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DPARTICLERENDERING_WRAP_PYTHON=OFF >/dev/null
# only what the C++ and fuzz tests run (not the ParaView plugin, the benchmarks or the GUI parts)
cmake --build "$build" -j "$(nproc)" --target ParticleRenderingCxxTests prCompareImages \
  prFuzzLAMMPSDump prFuzzMMPLD
echo "sanitizers: built in $(( $(date +%s) - start )) s"
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=0:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$build"
# (the fuzz tests set ASAN_OPTIONS themselves: detect_leaks=0, abort_on_error=1)
"$top/Scripts/with_xvfb.sh" ctest --output-on-failure --no-tests=error --timeout 900 -L "cxx|fuzz" "$@"
echo "sanitizers: done in $(( $(date +%s) - start )) s"
