#!/usr/bin/env bash
# Installs what tuff's main job and tests need on a Debian machine, as root:
# Mesa lavapipe (a CPU Vulkan driver), the Vulkan loader and headers, the Khronos
# validation layer, glslang (the shader freshness test recompiles the committed
# SPIR-V), Xvfb with libX11 (surfaces and swapchains need an X server) and valgrind
# (the adversarial suite runs under memcheck). Packages already installed are left alone; nothing is fetched
# when all are present.
set -euo pipefail

packages=(mesa-vulkan-drivers libvulkan1 libvulkan-dev vulkan-validationlayers
    glslang-tools xvfb libx11-6 xauth valgrind)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
    echo "install-deps: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

if ! command -v cargo >/dev/null 2>&1 && [ -f "$HOME/.cargo/env" ]; then
    # shellcheck disable=SC1091
    . "$HOME/.cargo/env"
fi
command -v cargo >/dev/null 2>&1 || {
    echo "install-deps: cargo is not installed; install Rust (https://rustup.rs) first" >&2
    exit 1
}
