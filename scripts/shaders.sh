#!/usr/bin/env bash
# Compiles the GLSL sources in shaders/src to SPIR-V in shaders/spv (or in the folder
# given as the first argument). The SPIR-V is committed, so building tuff needs no
# shader compiler; tests/shaders_fresh.rs runs this script into a temp folder and
# fails if the committed files differ.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/shaders/spv}"
if ! command -v glslangValidator >/dev/null; then
    echo "shaders.sh: glslangValidator not found (apt-get install glslang-tools)" >&2
    exit 1
fi
mkdir -p "$out"
for src in "$root"/shaders/src/*; do
    name="$(basename "$src")"
    glslangValidator -V --target-env vulkan1.0 -o "$out/$name.spv" "$src" >/dev/null \
        || { glslangValidator -V --target-env vulkan1.0 -o "$out/$name.spv" "$src"; exit 1; }
done
