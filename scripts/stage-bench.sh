#!/usr/bin/env bash
# The stage benchmark (issue: what safety costs per frame stage). Builds the `stages`
# binary five times (plain, with `multi_thread`, with `implicit_checks`, with `vulkano`
# for the vulkano peer, and without the hazard tracker: `--cfg tuff_untracked`), runs
# every variant over every configuration interleaved, and writes docs/stages/<label>.csv,
# .md and -<mode>.svg. Then times a full regeneration and, unless STAGES_NO_COMPILE=1,
# the clean compile of tuff against ash (scripts/compile-time.sh).
#
#   bash scripts/stage-bench.sh [label] [stages bench options...]
#
# Label defaults to `lavapipe`, which runs on Mesa lavapipe (TUFF_DEVICE=llvmpipe),
# headless and in a window under Xvfb. Options go to `stages bench` (see --help),
# e.g. `--rounds 1 --frames 20` for a quick look. STAGES_BUILD_ONLY=1 only builds
# target/stages/stages{,-mt,-checks,-vulkano,-untracked}, to carry to a machine
# without Rust (README.md says how the GPU tables were made).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/install-deps.sh
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"
label=${1:-lavapipe}
shift || true
mkdir -p target/stages
build() {
    cargo build -q --release -p tuff-examples --bin stages "$@"
    cp target/release/stages "target/stages/stages$suffix"
}
suffix=-mt build --features multi_thread
suffix=-checks build --features implicit_checks
suffix=-vulkano build --features vulkano
suffix= build
# Without the hazard tracker: a cfg, not a feature, in a target folder of its own
# (other RUSTFLAGS rebuild everything).
RUSTFLAGS="--cfg tuff_untracked" CARGO_TARGET_DIR=target/untracked \
    cargo build -q --release -p tuff-examples --bin stages
cp target/untracked/release/stages target/stages/stages-untracked
if [ "${STAGES_BUILD_ONLY:-0}" = 1 ]; then
    exit 0
fi
extra=()
if [ "$label" = lavapipe ]; then
    export TUFF_DEVICE=llvmpipe
    . scripts/xvfb.sh
    extra+=(--window)
fi
target/stages/stages bench --out docs/stages --label "$label" \
    --mt target/stages/stages-mt --checks target/stages/stages-checks \
    --untracked target/stages/stages-untracked --vulkano target/stages/stages-vulkano \
    "${extra[@]}" "$@"
# The generator's full run (regenerate into a scratch folder), and the clean compile
# of the generated crate against ash alone.
cargo build -q --release -p tuff-gen
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
start=$(date +%s.%N)
target/release/tuff-gen --out "$scratch/generated" > /dev/null
end=$(date +%s.%N)
python3 -c "import sys; print(f'\nRegeneration (\`target/release/tuff-gen --out DIR\`, release build): {float(sys.argv[2]) - float(sys.argv[1]):.1f} s\n')" "$start" "$end" | tee -a "docs/stages/$label.md"
if [ "${STAGES_NO_COMPILE:-0}" != 1 ]; then
    bash scripts/compile-time.sh | tee -a "docs/stages/$label.md"
fi
