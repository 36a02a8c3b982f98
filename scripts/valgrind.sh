#!/usr/bin/env bash
# Runs the adversarial suites (tests/soundness.rs, the secondaries' and subpasses'
# cases of tests/secondary_checks.rs and tests/subpass_checks.rs, and the render pass
# instance's subpass count of tests/recorded_state.rs) under
# valgrind's memcheck, on lavapipe with the validation layer, and fails on any
# invalid read or write, use of uninitialised memory or bad free that
# scripts/valgrind.supp does not name (only errors inside the dynamic loader, the
# Vulkan loader, the layer or the driver are named there). Needs valgrind
# (scripts/install-deps.sh installs it) and a display for the WSI tests
# (scripts/xvfb.sh). Arguments go to every test binary (a filter, for one).
#
# valgrind runs a program's threads one at a time, so the suites run in two lanes at
# once, each lane's output kept apart and printed when it ends: the soundness suite's
# tests split between the lanes (alternately, by name), the recorded-state case in the
# first, the two other suites in the second. With arguments (a filter), the soundness
# suite runs whole in the first lane.
set -euo pipefail
cd "$(dirname "$0")/.."
binary() {
    local suite=$1 bin
    bin=$(cargo test -p tuff-tests --test "$suite" --no-run --message-format=json 2>/dev/null |
        sed -n "s/.*\"executable\":\"\([^\"]*${suite}-[^\"]*\)\".*/\1/p" | tail -1)
    if [ -z "$bin" ]; then
        echo "valgrind.sh: could not build tests/$suite.rs" >&2
        exit 1
    fi
    echo "$bin"
}
memcheck() {
    (cd tests && valgrind --error-exitcode=1 --num-callers=40 \
        --suppressions=../scripts/valgrind.supp \
        "$1" --test-threads=1 "${@:2}")
}
soundness=$(binary soundness)
secondary=$(binary secondary_checks)
subpass=$(binary subpass_checks)
recorded=$(binary recorded_state)
subpasses_case=render_pass_instances_end_in_their_last_subpass_and_the_layer_agrees
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
if [ $# -eq 0 ]; then
    mapfile -t tests < <("$soundness" --list --format=terse | sed -n 's/: test$//p')
    first_half=() second_half=()
    for i in "${!tests[@]}"; do
        if [ $((i % 2)) = 0 ]; then first_half+=("${tests[$i]}"); else second_half+=("${tests[$i]}"); fi
    done
    (memcheck "$soundness" --exact "${first_half[@]}" &&
        memcheck "$recorded" --exact "$subpasses_case") > "$logs/1" 2>&1 &
    first=$!
    (memcheck "$soundness" --exact "${second_half[@]}" && memcheck "$secondary" &&
        memcheck "$subpass") > "$logs/2" 2>&1 &
    second=$!
else
    memcheck "$soundness" "$@" > "$logs/1" 2>&1 &
    first=$!
    (memcheck "$secondary" "$@" && memcheck "$subpass" "$@") > "$logs/2" 2>&1 &
    second=$!
fi
status=0
wait "$first" || status=1
cat "$logs/1"
wait "$second" || status=1
cat "$logs/2"
if [ "$status" != 0 ]; then
    echo "valgrind.sh: memcheck failed (above)" >&2
fi
exit "$status"
