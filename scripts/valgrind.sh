#!/usr/bin/env bash
# Runs the adversarial suites (tests/soundness.rs, and the secondaries' and
# subpasses' cases of tests/secondary_checks.rs and tests/subpass_checks.rs) under
# valgrind's memcheck, on lavapipe with the validation layer, and fails on any
# invalid read or write, use of uninitialised memory or bad free that
# scripts/valgrind.supp does not name (only errors inside the dynamic loader, the
# Vulkan loader, the layer or the driver are named there). Needs valgrind
# (scripts/install-deps.sh installs it) and a display for the WSI tests
# (scripts/xvfb.sh). Arguments go to every test binary (a filter, for one).
set -euo pipefail
cd "$(dirname "$0")/.."
for suite in soundness secondary_checks subpass_checks; do
    bin=$(cargo test -p tuff-tests --test "$suite" --no-run --message-format=json 2>/dev/null |
        sed -n "s/.*\"executable\":\"\([^\"]*${suite}-[^\"]*\)\".*/\1/p" | tail -1)
    if [ -z "$bin" ]; then
        echo "valgrind.sh: could not build tests/$suite.rs" >&2
        exit 1
    fi
    (cd tests && valgrind --error-exitcode=1 --num-callers=40 \
        --suppressions=../scripts/valgrind.supp \
        "$bin" --test-threads=1 "$@")
done
