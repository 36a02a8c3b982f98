#!/usr/bin/env bash
# Runs the adversarial suite (tests/soundness.rs) under valgrind's memcheck, on
# lavapipe with the validation layer, and fails on any invalid read or write, use of
# uninitialised memory or bad free that scripts/valgrind.supp does not name (only
# errors inside the dynamic loader, the Vulkan loader, the layer or the driver are
# named there). Needs valgrind (scripts/install-deps.sh installs it) and a display
# for the WSI tests (scripts/xvfb.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(cargo test -p tuff-tests --test soundness --no-run --message-format=json 2>/dev/null |
    sed -n 's/.*"executable":"\([^"]*soundness-[^"]*\)".*/\1/p' | tail -1)
if [ -z "$bin" ]; then
    echo "valgrind.sh: could not build tests/soundness.rs" >&2
    exit 1
fi
cd tests
exec valgrind --error-exitcode=1 --num-callers=40 \
    --suppressions=../scripts/valgrind.supp \
    "$bin" --test-threads=1 "$@"
