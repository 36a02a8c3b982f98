#!/usr/bin/env bash
# What the hazard tracker costs (issue: synchronisation): the stage benchmark's
# teapots with tuff checked (the default), with `auto_sync`, and built without the
# tracker (`--cfg tuff_untracked`, a build of its own), beside raw ash and raw ash
# under the validation layer with and without synchronization validation, interleaved
# in rounds. Writes docs/stages/<label>.csv, .md and -headless.svg.
#
#   bash scripts/hazard-bench.sh [label] [stages bench options...]
#
# Label defaults to `lavapipe-hazards` (Mesa lavapipe, TUFF_DEVICE=llvmpipe).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/install-deps.sh
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"
label=${1:-lavapipe-hazards}
shift || true
cargo build -q --release -p tuff-examples --bin stages
# A cfg, not a feature, in a target folder of its own (other RUSTFLAGS rebuild
# everything).
RUSTFLAGS="--cfg tuff_untracked" CARGO_TARGET_DIR=target/untracked \
    cargo build -q --release -p tuff-examples --bin stages
if [ "$label" = lavapipe-hazards ]; then
    export TUFF_DEVICE=llvmpipe
fi
target/release/stages bench --out docs/stages --label "$label" \
    --untracked target/untracked/release/stages "$@"
