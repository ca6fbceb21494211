#!/usr/bin/env bash
# Runs a command with DISPLAY set to a private Xvfb server (OpenGL from Mesa llvmpipe).
# The server picks a free display itself (-displayfd), so concurrent runs never collide.
# An existing DISPLAY is used as it is when PR_USE_EXISTING_DISPLAY=1; PR_XVFB_SCREEN sets the
# screen (default 1600x1200x24).
set -euo pipefail
if [ "${PR_USE_EXISTING_DISPLAY:-0}" = 1 ] && [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
fifo=$(mktemp -u)
mkfifo "$fifo"
# -noreset: without it Xvfb resets when its last client disconnects, and a window opened
# during the reset aborts with "bad X server connection" (tests that close and reopen windows)
Xvfb -noreset -displayfd 3 -screen 0 "${PR_XVFB_SCREEN:-1600x1200x24}" -nolisten tcp 3>"$fifo" >/dev/null 2>&1 &
xvfb_pid=$!
trap 'kill $xvfb_pid 2>/dev/null || true; rm -f "$fifo"' EXIT
read -r display <"$fifo"
export DISPLAY=":$display"
"$@"
