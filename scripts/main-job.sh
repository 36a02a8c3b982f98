#!/usr/bin/env bash
# The main job: regenerate generated/ and its validation coverage report from the
# pinned registry (vk.xml and validusage.json at the repository root), then render
# the scenes headless on the Vulkan device (lavapipe on a machine without a
# GPU), print their frame rates, and measure what tessellation accuracy costs.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/install-deps.sh
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"

cargo run --release -q -p tuff-gen
echo "main-job: coverage report in generated/VALIDATION.md, generated/validation.json and generated/validation.svg"

cargo build --release -q -p tuff-examples --bins
mkdir -p out
# 60 frames each at 512x512; the PNG is the last frame.
for scene in triangle teapots bezier textured_quad; do
    "target/release/$scene" --frames 60 --width 512 --height 512 --out "out/$scene.png"
done
# The deferred scene: a G-buffer subpass recorded by four worker threads into
# secondaries, and a lighting subpass reading it as input attachments. Its workers
# run on threads of their own only with `multi_thread` (tuff's wrappers cross threads
# only then), so it is built again with that feature, and beside it its raw-ash twin.
cargo build --release -q -p tuff-examples --features multi_thread --bin deferred --bin deferred_ash
target/release/deferred --count 2000 --threads 4 --frames 60 --width 512 --height 512 --out out/deferred.png
target/release/deferred_ash --count 2000 --threads 4 --frames 60 --width 512 --height 512 --out out/deferred_ash.png
# The compute example: a million sums on the device, each checked on the host.
target/release/compute
target/release/bezier_levels --size 512 --frames 30 --svg out/bezier-levels.svg
echo "main-job: scenes in $(pwd)/out/triangle.png, $(pwd)/out/teapots.png, $(pwd)/out/bezier.png, $(pwd)/out/textured_quad.png and $(pwd)/out/deferred.png"
