#!/usr/bin/env bash
# Every check CI runs: formatting, clippy, and the whole test suite, with the runtime
# in both threading modes. Vulkan tests run on Mesa lavapipe with the Khronos
# validation layer on.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/install-deps.sh
. scripts/xvfb.sh
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"

cargo fmt --all --check
cargo clippy --workspace --all-targets -- -D warnings
cargo clippy -p tuff-runtime -p tuff-tests --all-targets --features tuff-runtime/multi_thread -- -D warnings
cargo clippy -p tuff-tests --all-targets --features multi_thread -- -D warnings
# The tuff crate alone, as a dependency builds it: default features, one extension,
# and every extension it emits.
cargo clippy -p tuff -- -D warnings
cargo clippy -p tuff --features khr_swapchain -- -D warnings
cargo clippy -p tuff --features all_extensions -- -D warnings
cargo test --workspace
# The runtime again with Vrc = Arc and Vutex = a mutex.
cargo test -p tuff-runtime -p tuff-tests --features tuff-runtime/multi_thread,tuff-tests/multi_thread
# The adversarial suite under valgrind's memcheck: no invalid read or write, no use
# of uninitialised memory, outside the few loader errors scripts/valgrind.supp names.
bash scripts/valgrind.sh
# The generator outside the emitted subset: another registry and every extension
# ash has, regenerated into scratch crates and compiled (scripts/wide-check.sh).
bash scripts/wide-check.sh 1.4.309 all-ash-exts
