#!/usr/bin/env bash
# Every check CI runs: formatting, clippy, and the whole test suite, with the runtime
# in both threading modes. Vulkan tests run on Mesa lavapipe with the Khronos
# validation layer on.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/install-deps.sh
. scripts/xvfb.sh
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"
# A clean run builds each crate once; incremental caches would only take disk.
export CARGO_INCREMENTAL=0

# Each step says how long it took, so the run's cost can be read off its log.
step() {
    local start=$SECONDS
    "$@"
    echo "test.sh: $((SECONDS - start)) s: $*" >&2
}

step cargo fmt --all --check
step cargo clippy --workspace --all-targets -- -D warnings
step cargo clippy -p tuff-runtime -p tuff-tests --all-targets --features tuff-runtime/multi_thread -- -D warnings
step cargo clippy -p tuff-tests --all-targets --features multi_thread -- -D warnings
# The tuff crate alone, as a dependency builds it: default features, each of a few
# single extensions (each pulls in only the features its extension depends on), and
# every extension it emits, with the runtime in both threading modes. Clippy type-checks
# each without code generation, which the test build below does once.
step cargo clippy -p tuff -- -D warnings
for feature in khr_swapchain khr_acceleration_structure ext_mesh_shader khr_video_decode_queue; do
    step cargo clippy -q -p tuff --features "$feature" -- -D warnings
done
step cargo clippy -p tuff --features all_extensions -- -D warnings
step cargo clippy -p tuff --features all_extensions,multi_thread -- -D warnings
# Docs build without a broken link or stray HTML, with default features and with
# every extension.
RUSTDOCFLAGS="-D warnings" step cargo doc --workspace --no-deps
RUSTDOCFLAGS="-D warnings" step cargo doc -p tuff --no-deps --features all_extensions
step cargo test --workspace
# The runtime again with Vrc = Arc and Vutex = a mutex, and the tests whose code takes
# a different path with it: the threaded soundness cases, workers recording secondaries
# (threads.rs) and the deferred scene's (examples/tests/deferred.rs), the wrappers, submission
# (queue locks), mapped memory and the layer's object names. Everything else locks the
# same Vutex in both modes (a double lock panics in one and deadlocks in the other, so
# the first pass finds either), and clippy above compiles every test with the feature.
step cargo test -p tuff-runtime -p tuff-tests -p tuff-examples \
    --features tuff-runtime/multi_thread,tuff-tests/multi_thread,tuff-examples/multi_thread \
    --lib --test soundness --test wrappers --test submission_checks --test runtime_memory --test oracle --test threads \
    --test deferred
# The stage benchmark's vulkano peer (an optional feature: vulkano is a benchmark
# dependency only): it builds, passes clippy, and draws raw ash's and tuff's image.
# In a target folder of its own, removed after: with the feature every scene binary
# is built again (about 1 GB), which nothing later needs.
CARGO_TARGET_DIR=target/peer step cargo clippy -p tuff-examples --all-targets --features vulkano -- -D warnings
CARGO_TARGET_DIR=target/peer step cargo test -p tuff-examples --features vulkano --test vulkano_peer
rm -rf target/peer
# The adversarial suite under valgrind's memcheck: no invalid read or write, no use
# of uninitialised memory, outside the few loader errors scripts/valgrind.supp names.
step bash scripts/valgrind.sh
# Leaks: the scenes for 100 frames and a window through 30 resizes under memcheck's
# leak check; a block lost with a frame in tuff's code fails (scripts/leaks.sh).
step bash scripts/leaks.sh
# The generator outside the pinned inputs: each newer registry, with every extension
# ash has, regenerated into a scratch crate and compiled (scripts/wide-check.sh); and
# Vulkan 1.4 as the core version, whose commands ash has no table for.
step bash scripts/wide-check.sh all-1.4.309 all-1.4.330 core14-1.4.309
# A Vulkan 1.4 program through that crate (examples/core14): on lavapipe, a 1.3
# device, its 1.4 call is refused with Error::VersionNotSupported, layer quiet.
TUFF_DEVICE=llvmpipe step bash scripts/core14.sh
rm -rf target/core14
echo "test.sh: target folder $(du -sh target | cut -f1)"
