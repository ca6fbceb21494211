#!/usr/bin/env bash
# The README's GUI screenshot (Plugin/Documentation/paraview-first-minute.png): LAMMPS writes the
# lj_droplets dump series, the ParaView GUI opens it as in the README's first minute
# (Scripts/gui_screenshot.py, run with paraview --script), and the screen of a private Xvfb is
# captured with xwd and converted by Scripts/xwd_to_png.py. ParaView runs with --dr and a private
# XDG_CONFIG_HOME (no user settings, and so no welcome dialog, which is modal and would block the script; the same in
# ParaView 5.11, 5.13 and 6.1). xwd comes with x11-apps (Scripts/install_dependencies.sh).
# usage: Scripts/gui_screenshot.sh [OUTPUT.png]   (from anywhere, after Scripts/build.sh;
# BUILD_DIR as for build.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/Plugin/Documentation/paraview-first-minute.png}
work=$(mktemp -d)
(cd "$work" && env -u OMPI_COMM_WORLD_SIZE -u OMPI_COMM_WORLD_RANK \
  lmp -in "$root/Testing/Data/Generators/in.lj_droplets" -var outdir "$work" -log none -screen none)

# the capture, on a private Xvfb whose screen is the picture's size (the main window fills it)
capture() {
  paraview --dr --script="$root/Scripts/gui_screenshot.py" >"$work/paraview.log" 2>&1 &
  local paraview_pid=$!
  for _ in $(seq 1 300); do
    [ -f "$PR_DONE" ] && break
    sleep 1
  done
  if [ "$(cat "$PR_DONE" 2>/dev/null)" != rendered ]; then
    echo "the GUI script did not finish:" >&2
    cat "$PR_DONE" "$work/paraview.log" >&2 2>/dev/null || true
    kill "$paraview_pid" 2>/dev/null || true
    return 1
  fi
  sleep 15 # let the GUI settle (the last render, the panels)
  xwd -root -silent | /usr/bin/python3 "$root/Scripts/xwd_to_png.py" "$out"
  kill "$paraview_pid" 2>/dev/null || true
}
trap 'rm -rf "$work"' EXIT
export -f capture
export root out work XDG_CONFIG_HOME="$work/config"
export PR_PLUGIN="${BUILD_DIR:-$root/build}/lib/paraview-plugins/ParticleRendering/ParticleRendering.so"
export PR_DUMPS="$work" PR_DONE="$work/done"
PR_USE_EXISTING_DISPLAY=0 PR_XVFB_SCREEN=1280x800x24 "$root/Scripts/with_xvfb.sh" bash -c capture
echo "wrote $out"
