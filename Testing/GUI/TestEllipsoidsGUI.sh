#!/usr/bin/env bash
# A LAMMPS ellipsoid dump in the ParaView GUI: TestEllipsoidsGUI.py opens the bundled Gay-Berne
# dump in a Particle Render View; the Particles representation (Shape Automatic) must draw
# oriented ellipsoids opaque, with voxel-cone AO (darker than without) and translucent (another
# picture). Needs DISPLAY (ctest runs under Scripts/with_xvfb.sh); --dr and a private
# XDG_CONFIG_HOME as TestSNDFRefinementGUI.sh. A GUI that never answers is reported after 300 s (a
# hang guard, not a speed limit).
# usage: TestEllipsoidsGUI.sh PLUGIN DATA_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null || true; rm -rf "$work"' EXIT
export XDG_CONFIG_HOME="$work/config" PR_PLUGIN="$1" PR_DATA="$2" PR_WORK="$work" \
  PR_RESULT="$work/result"
paraview --dr --script="$here/TestEllipsoidsGUI.py" >"$work/paraview.log" 2>&1 &
pid=$!
for _ in $(seq 1 300); do
  if [ -f "$work/result" ] && grep -q -e '^done$' -e '^error$' "$work/result"; then
    break
  fi
  if ! kill -0 "$pid" 2>/dev/null; then
    cat "$work/paraview.log"
    echo "FAIL: paraview ended"
    exit 1
  fi
  sleep 1
done
cat "$work/result" 2>/dev/null || true
if ! grep -q '^done$' "$work/result" 2>/dev/null; then
  cat "$work/paraview.log"
  echo "FAIL: the GUI script failed or did not finish"
  exit 1
fi
status=0
grep -q '^representation Particles shape Automatic$' "$work/result" ||
  { echo "FAIL: not shown as Particles with Shape Automatic"; status=1; }
for name in opaque ao translucent; do
  grep -q "^$name 1 " "$work/result" || { echo "FAIL: $name: not drawn as ellipsoids"; status=1; }
done
opaque=$(awk '$1 == "opaque" {print $3}' "$work/result")
ao=$(awk '$1 == "ao" {print $3}' "$work/result")
translucent=$(awk '$1 == "translucent" {print $3}' "$work/result")
if ! awk -v o="$opaque" -v a="$ao" -v t="$translucent" 'BEGIN {exit !(a < o - 1 && t != a)}'; then
  echo "FAIL: brightness opaque $opaque, AO $ao, translucent $translucent: AO does not darken or translucency changes nothing"
  status=1
fi
[ "$status" -eq 0 ] && echo "PASSED"
exit "$status"
