#!/usr/bin/env bash
# ThreadSanitizer on the threads stress test (tests/threads.rs, `multi_thread`):
# `bash scripts/tsan.sh [SECONDS]` (3 by default). Needs the nightly toolchain. Its
# std is not instrumented (that needs the rust-src component, `-Zbuild-std`), so races
# inside std's own code (an `Arc`'s drop) are reported without being real; the script
# lists every report by where it is and fails on one whose place is tuff's code (the
# crate or its runtime). Reports inside the driver and the validation layer are
# theirs, listed and not failed.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/xvfb.sh
seconds=${1:-3}
export RUSTFLAGS="-Zsanitizer=thread -Cunsafe-allow-abi-mismatch=sanitizer"
export CARGO_TARGET_DIR=target/tsan
bin=$(cargo +nightly test -q -p tuff-tests --features multi_thread --test threads \
    --target x86_64-unknown-linux-gnu --no-run --message-format=json 2>/dev/null |
    sed -n 's/.*"executable":"\([^"]*threads-[^"]*\)".*/\1/p' | tail -1)
log=$(mktemp)
# scripts/xvfb.sh's own trap is replaced here: stop its server, if it started one.
trap 'rm -f "$log"; if [ -n "${xvfb_pid:-}" ]; then kill "$xvfb_pid" 2>/dev/null || true; fi' EXIT
(cd tests && TUFF_STRESS_SECONDS=$seconds TSAN_OPTIONS="halt_on_error=0" "$bin" \
    --exact threaded::eight_threads_record_and_churn_objects_at_once --nocapture) > "$log" 2>&1 || true
grep -q "1 passed" "$log" || { cat "$log"; echo "tsan.sh: the test failed" >&2; exit 1; }
echo "tsan.sh: reports by place:"
grep "SUMMARY: ThreadSanitizer" "$log" | sed 's/ (BuildId.*//; s|/rustc/[0-9a-f]*/||' |
    sort | uniq -c | sort -rn
if grep "SUMMARY: ThreadSanitizer" "$log" | grep -E "generated/src|runtime/src|tuff::|tuff_runtime::"; then
    echo "tsan.sh: a report in tuff's code (above)" >&2
    exit 1
fi
