#!/usr/bin/env bash
# Instructions per frame of the teapots frame loop on lavapipe, counted by valgrind's
# callgrind (issue: safety at the speed of raw ash): what each stage of a one-teapot
# frame costs tuff on the host, with the hazard tracker and without it, beside raw
# ash's recording. A count of instructions is not a time, but it is the same on every
# run: where a stage's cost moves by less than the noise of a timed run, this shows
# it. The GPU machine gives the times (README, "The stage benchmark").
#
#   bash scripts/frame-instructions.sh [frames]
#
# Builds the release `stages` binary with and without the hazard tracker (as
# scripts/stage-bench.sh does), then prints, per frame, the inclusive
# instructions of: the frame's recording (`render::record_frame`, raw ash's
# `raw_ash::record_frame`), the two submissions (the frame's and the copy-out's,
# `Frame::submit`), and the copy-out's recording (`render::record_readback`).
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-300}
. scripts/install-deps.sh
. scripts/xvfb.sh
command -v valgrind >/dev/null || { echo "frame-instructions: needs valgrind" >&2; exit 1; }
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"
cargo build -q --release -p tuff-examples --bin stages
RUSTFLAGS="--cfg tuff_untracked" CARGO_TARGET_DIR=target/untracked \
    cargo build -q --release -p tuff-examples --bin stages
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
count() { # variant binary collect-function
    TUFF_DEVICE=llvmpipe valgrind --tool=callgrind --callgrind-out-file="$out/$1.out" \
        --toggle-collect="$3*" "$2" run --variant "$1" --count 1 --frames "$frames" \
        --size 1 >/dev/null 2>"$out/$1.log" || { cat "$out/$1.log" >&2; exit 1; }
    callgrind_annotate --inclusive=yes --threshold=100 "$out/$1.out" >"$out/$1.txt"
}
count ash target/release/stages tuff_examples::stages::ash_frames::headless
count tuff target/release/stages tuff_examples::stages::tuff_frames::headless
count tuff-untracked target/untracked/release/stages tuff_examples::stages::tuff_frames::headless
per_frame() { # variant function
    local n
    n=$(grep -E "\?\?\?:$2 \[" "$out/$1.txt" | head -1 | awk '{gsub(",", "", $1); print $1}')
    # The timed frames and the warm-up frames (5) ran.
    [ -n "$n" ] && echo $((n / (frames + 5))) || echo "-"
}
printf '%-16s %12s %12s %12s\n' "per frame" "command" "submit (2)" "copy-out rec"
printf '%-16s %12s %12s %12s\n' "raw ash" "$(per_frame ash tuff_examples::raw_ash::record_frame)" "-" "-"
for v in tuff tuff-untracked; do
    printf '%-16s %12s %12s %12s\n' "$v" \
        "$(per_frame $v tuff_examples::render::record_frame)" \
        "$(per_frame $v tuff::routine::frames::Frame::submit)" \
        "$(per_frame $v tuff_examples::render::record_readback)"
done
