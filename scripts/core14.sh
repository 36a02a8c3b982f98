#!/usr/bin/env bash
# Vulkan 1.4 on ash 0.38: regenerates tuff from the 1.4.309 registry with
# api_version = "1.4" into target/core14/tuff, builds examples/core14 against it, and
# runs it (on lavapipe, a 1.3 device, its 1.4 call must be refused with
# Error::VersionNotSupported; on a 1.4 device it must succeed), under the validation
# layer, failing on any message.
#
#   bash scripts/core14.sh            generate, build (debug) and run
#   CORE14_RELEASE=1 bash scripts/core14.sh   build release only, for the GPU machine
#                                     (target/core14/build/release/tuff-core14)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
out="$root/target/core14"
mkdir -p "$out"
cfg="$out/core14.toml"
sed -e 's/^api_version = "1.3"/api_version = "1.4"/' \
    -e "s#\"reference/vk.xml\"#\"$root/reference/vk.xml\"#" \
    -e "s#\"examples/src\"#\"$root/examples/src\"#" \
    "$root/tuff-gen.toml" >"$cfg"
cargo run -q -p tuff-gen -- --registry "$root/../shared/registry/1.4.309/vk.xml" \
    --config "$cfg" --out "$out/tuff" --allow-shrink >"$out/gen.log" 2>&1 || {
    cat "$out/gen.log"
    exit 1
}
# The workspace's lock file, so the example builds offline against the same ash.
cp "$root/Cargo.lock" "$root/examples/core14/Cargo.lock"
export CARGO_TARGET_DIR="$out/build"
if [ "${CORE14_RELEASE:-0}" = 1 ]; then
    cargo build -q --offline --release --manifest-path "$root/examples/core14/Cargo.toml"
    exit 0
fi
cargo build -q --offline --manifest-path "$root/examples/core14/Cargo.toml"
"$CARGO_TARGET_DIR/debug/tuff-core14"
# What the crate defines because ash lacks it, against the C headers of 1.4.309.
cargo test -q --offline --manifest-path "$root/examples/core14/Cargo.toml" -- --nocapture
