#!/usr/bin/env bash
# The threads table (README, "Threads"): the deferred scene recorded by 1 to 16
# worker threads at 1,000 to 100,000 objects, tuff beside its raw-ash twin, into
# docs/stages/threads-<label>.csv and .md. Builds the two scene binaries with
# `multi_thread` (tuff's workers need it to run on threads of their own) and the
# `threads` runner into target/threads/.
#
#   bash scripts/threads-bench.sh [label] [threads options...]
#
# Label defaults to `lavapipe` (TUFF_DEVICE=llvmpipe). Options go to `threads`
# (see --help), e.g. `--rounds 1 --frames 5` for a quick look. THREADS_BUILD_ONLY=1
# only builds target/threads/, to carry to a machine without Rust.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/install-deps.sh
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"
label=${1:-lavapipe}
shift || true
mkdir -p target/threads
cargo build -q --release -p tuff-examples --features multi_thread --bin deferred --bin deferred_ash --bin threads
cp target/release/deferred target/release/deferred_ash target/release/threads target/threads/
if [ "${THREADS_BUILD_ONLY:-0}" = 1 ]; then
    exit 0
fi
if [ "$label" = lavapipe ]; then
    export TUFF_DEVICE=llvmpipe
fi
target/threads/threads --tuff target/threads/deferred --ash target/threads/deferred_ash \
    --out docs/stages --label "$label" --made-by "scripts/threads-bench.sh $label $*" "$@"
