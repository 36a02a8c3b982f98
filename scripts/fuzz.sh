#!/usr/bin/env bash
# Fuzz one target for a while: `bash scripts/fuzz.sh TARGET SECONDS [JOBS]`, TARGET one
# of registry, registry_edits, validusage, config, spirv (fuzz/fuzz_targets/). Needs
# a nightly toolchain and cargo-fuzz (`cargo install cargo-fuzz`). The working corpus
# grows in fuzz/corpus/TARGET (ignored), seeded from fuzz/seeds/TARGET (and, for
# spirv, the committed shaders); a crash lands in fuzz/artifacts/TARGET: copy it to
# fuzz/regressions/TARGET, where tests/fuzz_corpus.rs replays it on every test run,
# then fix it. FUZZ_BUILD_ONLY=1 builds the targets and stops. With JOBS above 1,
# libFuzzer runs that many processes and writes each one's log to fuzz-N.log here.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"
target=${1:?a fuzz target}
seconds=${2:-60}
jobs=${3:-1}
if [ "${FUZZ_BUILD_ONLY:-}" = 1 ]; then
    cargo +nightly fuzz build --fuzz-dir fuzz -O
    exit
fi
corpus=fuzz/corpus/$target
mkdir -p "$corpus"
cp -n fuzz/seeds/"$target"/* "$corpus"/ 2>/dev/null || true
[ "$target" = spirv ] && cp -n shaders/spv/*.spv "$corpus"/
# Inputs past 1 MB are not what the readers are for; the registry seed is 135 KB.
parallel=()
[ "$jobs" -gt 1 ] && parallel=(-jobs="$jobs" -workers="$jobs")
cargo +nightly fuzz run --fuzz-dir fuzz -O "$target" "$corpus" -- \
    -max_total_time="$seconds" -max_len=1048576 "${parallel[@]}" -print_final_stats=1
