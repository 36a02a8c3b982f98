#!/usr/bin/env bash
# Leaks: the teapots scene and the deferred scene (workers recording secondaries), 100
# frames each headless on lavapipe, and the teapots in a window through 30 resizes of
# the resize storm (a display: scripts/xvfb.sh), under valgrind's memcheck with
# --leak-check=full.
# Fails on a block definitely lost whose allocation has a frame in tuff's code (the
# crate, its runtime or the scenes); blocks lost inside the driver alone are counted
# and listed, not failed: lavapipe loses some (the deferred scene's most of all, the
# same in its raw-ash twin; README, "Reliability"). Builds the scenes' debug binaries
# (the test command has them already). LEAKS_FRAMES sets the frame count.
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${LEAKS_FRAMES:-100}
. scripts/xvfb.sh
cargo build -q -p tuff-examples --bin teapots --bin deferred
logs=$(mktemp -d)
# scripts/xvfb.sh's own trap is replaced here: stop its server, if it started one
# (never `kill 0`: that is the whole process group, the caller's test run included).
trap 'rm -rf "$logs"; if [ -n "${xvfb_pid:-}" ]; then kill "$xvfb_pid" 2>/dev/null || true; fi' EXIT
status=0
check() {
    local name=$1 log=$logs/$1.log
    shift
    TUFF_DEVICE=llvmpipe valgrind --leak-check=full --show-leak-kinds=definite \
        --num-callers=40 --suppressions=scripts/valgrind.supp --log-file="$log" \
        "$@" > /dev/null
    local lost ours
    lost=$(sed -n 's/.*definitely lost: \([0-9,]*\) bytes in \([0-9,]*\) blocks.*/\1 bytes in \2 blocks/p' "$log")
    # A loss record: its header line and the stack under it, up to the blank line.
    ours=$(awk '/are definitely lost in loss record/{r=$0; mine=0; next}
        r!="" && /(tuff|tuff_runtime|tuff_examples)::/{mine=1}
        r!="" && /^==[0-9]+== $/{if (mine) print r; r=""}' "$log")
    echo "leaks.sh: $name: definitely lost ${lost:-0 bytes}"
    if [ -n "$ours" ]; then
        echo "leaks.sh: $name: lost blocks allocated in tuff's code:" >&2
        echo "$ours" >&2
        cat "$log" >&2
        status=1
    fi
}
headless=(--frames "$frames" --width 64 --height 64)
check teapots target/debug/teapots --count 4 "${headless[@]}" --out "$logs/teapots.png"
check deferred target/debug/deferred --count 16 --threads 2 "${headless[@]}" --out "$logs/deferred.png"
check storm target/debug/teapots --count 4 --window --resizes 30 --width 200 --height 150
exit "$status"
