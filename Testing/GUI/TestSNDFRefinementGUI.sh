#!/usr/bin/env bash
# The ParaView GUI refines S-NDF shading by itself (pqParticleProgressiveRefinement): the script
# TestSNDFRefinementGUI.py renders a Particle Render View once; the view must then be rendered
# again without further requests until its S-NDFs hold the target 160 samples (10 renders of 16
# after the render of the change; without the plugin's behaviour the GUI's own renders after the
# script reach 48), and no more renders may follow. Needs DISPLAY (ctest runs
# under Scripts/with_xvfb.sh). --dr and a private XDG_CONFIG_HOME: no user settings, and so no
# modal welcome dialog (the same in ParaView 5.11, 5.13 and 6.1). A GUI that never converges is
# reported after 600 s (a hang guard, not a speed limit: the refinement takes a few seconds).
# usage: TestSNDFRefinementGUI.sh PLUGIN
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null || true; rm -rf "$work"' EXIT
export XDG_CONFIG_HOME="$work/config" PR_PLUGIN="$1" PR_RESULT="$work/result"
paraview --dr --script="$here/TestSNDFRefinementGUI.py" >"$work/paraview.log" 2>&1 &
pid=$!
samples=0
for _ in $(seq 1 600); do
  if [ -f "$work/result" ]; then
    if grep -q error "$work/result"; then
      cat "$work/result"
      echo "FAIL: the GUI script failed"
      exit 1
    fi
    read -r renders samples <"$work/result" || true
    [ "${samples:-0}" -ge 160 ] && break
  fi
  if ! kill -0 "$pid" 2>/dev/null; then
    cat "$work/paraview.log"
    echo "FAIL: paraview ended"
    exit 1
  fi
  sleep 1
done
if [ "${samples:-0}" -lt 160 ]; then
  cat "$work/result" "$work/paraview.log" 2>/dev/null || true
  echo "FAIL: the view did not converge (renders samples: $(cat "$work/result" 2>/dev/null))"
  exit 1
fi
read -r renders samples <"$work/result"
sleep 5 # no render may follow convergence
read -r later later_samples <"$work/result"
echo "renders of the view after the script's render: $renders (samples $samples); 5 s later: $later"
if [ "$later" != "$renders" ]; then
  echo "FAIL: the view kept rendering after it converged"
  exit 1
fi
echo "PASSED"
