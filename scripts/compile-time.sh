#!/usr/bin/env bash
# Compile time of the generated crate against ash alone, side by side in one run:
# each is built (debug, default features) into its own empty target folder, so the
# tuff figure includes building ash, tuff-runtime and their dependencies.
set -euo pipefail
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
python3 - "$t0" "$t1" "$t2" <<'PY'
import sys
t0, t1, t2 = map(float, sys.argv[1:])
ash, tuff = t1 - t0, t2 - t1
print("| build (debug, clean target) | seconds |")
print("|---|---|")
print(f"| ash alone | {ash:.1f} |")
print(f"| tuff (with ash, tuff-runtime) | {tuff:.1f} |")
print(f"| ratio tuff / ash | {tuff / ash:.2f}x |")
PY
