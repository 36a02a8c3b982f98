#!/usr/bin/env bash
# Compile time of the generated crate against ash alone, side by side in one run:
# each is built (debug) into its own empty target folder, so the tuff figures
# include building ash, tuff-runtime and their dependencies: tuff with default
# features, then with every extension it emits. Incremental compilation is off, as
# cargo builds a dependency from a registry (it is on only for workspace members,
# where it costs about 4 s more on the every-extension build to write its caches).
set -euo pipefail
export CARGO_INCREMENTAL=0
cd "$(dirname "$0")/.."
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"
cargo fetch -q
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
t0=$(date +%s.%N)
CARGO_TARGET_DIR="$work/ash" cargo build -q --offline -p ash
t1=$(date +%s.%N)
CARGO_TARGET_DIR="$work/tuff" cargo build -q --offline -p tuff
t2=$(date +%s.%N)
CARGO_TARGET_DIR="$work/all" cargo build -q --offline -p tuff --features all_extensions
t3=$(date +%s.%N)
python3 - "$t0" "$t1" "$t2" "$t3" <<'PY'
import sys
t0, t1, t2, t3 = map(float, sys.argv[1:])
ash, tuff, every = t1 - t0, t2 - t1, t3 - t2
print("| build (debug, clean target) | seconds | ratio to ash |")
print("|---|---|---|")
print(f"| ash alone | {ash:.1f} | 1.00x |")
print(f"| tuff, default features (with ash, tuff-runtime) | {tuff:.1f} | {tuff / ash:.2f}x |")
print(f"| tuff, `--features all_extensions` | {every:.1f} | {every / ash:.2f}x |")
PY
