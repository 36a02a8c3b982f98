#!/usr/bin/env bash
# Lines of code of the teapots scene written on tuff and written in raw ash, without
# shaders. Counted: lines that are neither blank nor only a comment (doc comments
# included), so the tuff side's docs do not count against it, outside `#[cfg(test)]`
# modules (unit tests are not the program; the ash side has none). Not counted on
# either side: what both use and that makes no Vulkan call (the teapot's patches and
# mesh, the camera, the grid and its uniform blocks in scenes/teapot_grid.rs, PNG
# output, the error exit in lib.rs).
set -euo pipefail
cd "$(dirname "$0")/../examples/src"
# A `#[cfg(test)]` module runs from its attribute to the file's end (where rustfmt
# and this project put it).
count() {
    for f in "$@"; do sed '/^#\[cfg(test)\]/,$d' "$f"; done | grep -v -E '^\s*$|^\s*//' | wc -l
}
tuff_headless=(bin/teapots.rs scenes/teapots.rs gpu.rs render.rs headless.rs pipeline.rs cli.rs)
echo "| Teapots | Files | Lines of code |"
echo "|---|---|---:|"
echo "| tuff, headless | ${tuff_headless[*]} | $(count "${tuff_headless[@]}") |"
echo "| tuff, headless and windowed | the same and window.rs | $(count "${tuff_headless[@]}" window.rs) |"
echo "| raw ash, headless | bin/teapots_ash.rs | $(count bin/teapots_ash.rs) |"
