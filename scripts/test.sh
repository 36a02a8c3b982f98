#!/usr/bin/env bash
# Every check CI runs: formatting, clippy, and the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/install-deps.sh
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"

cargo fmt --all --check
cargo clippy --workspace --all-targets -- -D warnings
cargo test --workspace
