#!/usr/bin/env bash
# Sourced by the test and main-job scripts: when no X display is set, starts Xvfb on a
# free display number and exports DISPLAY, so surfaces, swapchains and windowed
# scenes run on a machine without a screen. The server stops when the script exits.
if [ -z "${DISPLAY:-}" ]; then
    command -v Xvfb >/dev/null || { echo "xvfb.sh: Xvfb not found (apt-get install xvfb)" >&2; exit 1; }
    for n in $(seq 90 120); do
        [ -e "/tmp/.X11-unix/X$n" ] || [ -e "/tmp/.X$n-lock" ] || break
    done
    Xvfb ":$n" -screen 0 1280x1024x24 -nolisten tcp -noreset >/dev/null 2>&1 &
    xvfb_pid=$!
    trap 'kill "$xvfb_pid" 2>/dev/null || true' EXIT
    for _ in $(seq 1 50); do
        [ -e "/tmp/.X11-unix/X$n" ] && break
        sleep 0.1
    done
    [ -e "/tmp/.X11-unix/X$n" ] || { echo "xvfb.sh: Xvfb did not start on :$n" >&2; exit 1; }
    export DISPLAY=":$n"
fi
