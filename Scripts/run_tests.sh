#!/usr/bin/env bash
# README command 2: install what is needed, build, and run the whole CTest suite headless
# (Xvfb + Mesa llvmpipe). Extra arguments go to ctest (e.g. -R Python, -L cxx).
#   bash Scripts/run_tests.sh --debian trixie|sid [ctest args]
# does the same inside a Debian 13 (ParaView 5.13) or Debian unstable (ParaView 6.1) chroot
# (Scripts/debian_chroot.sh; as root), building into build-debian-<release>/.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = --debian ]; then
  release=${2:?"--debian needs a release: trixie or sid"}
  shift 2
  export BUILD_DIR=$top/build-debian-$release
  exec bash "$top/Scripts/debian_chroot.sh" "$release" bash "$top/Scripts/run_tests.sh" "$@"
fi
start=$SECONDS
"$top/Scripts/install_dependencies.sh"
echo "run_tests: dependencies checked in $((SECONDS - start)) s"
start=$SECONDS
"$top/Scripts/build.sh"
echo "run_tests: built in $((SECONDS - start)) s"
build=${BUILD_DIR:-$top/build}
cd "$build"
# Mesa prints every OpenGL error it sees; such a line fails the test (pr_fail_on_mesa_errors)
export MESA_DEBUG=${MESA_DEBUG:-1}
"$top/Scripts/with_xvfb.sh" ctest --output-on-failure --no-tests=error --timeout 900 "$@"
