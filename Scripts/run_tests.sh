#!/usr/bin/env bash
# README command 2: install what is needed, build, and run the whole CTest suite headless
# (Xvfb + Mesa llvmpipe). Extra arguments go to ctest (e.g. -R Python, -L cxx).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/Scripts/install_dependencies.sh"
"$top/Scripts/build.sh"
build=${BUILD_DIR:-$top/build}
cd "$build"
# Mesa prints every OpenGL error it sees; such a line fails the test (pr_fail_on_mesa_errors)
export MESA_DEBUG=${MESA_DEBUG:-1}
"$top/Scripts/with_xvfb.sh" ctest --output-on-failure --no-tests=error --timeout 900 "$@"
