#!/usr/bin/env bash
# Lines of code of each scene written on tuff and written in raw ash, without shaders.
# Both sides have the same structure: a shared part (tuff: gpu.rs, render.rs,
# headless.rs, pipeline.rs, cli.rs; raw ash: raw_ash.rs) and a part per scene. The
# tuff side also carries the window path's hooks in its shared part (window.rs itself
# is counted only in the last row); the raw-ash side is headless only.
#
# Counted: lines that are neither blank nor only a comment (doc comments included),
# so the tuff side's docs do not count against it, outside `#[cfg(test)]` modules
# (unit tests are not the program; the ash side has none). Not counted on either
# side: what both use and that makes no Vulkan call (the scenes as data in
# scenes/triangle_vertices.rs, scenes/teapot_grid.rs and scenes/bezier_view.rs, the
# teapot's patches and mesh, the camera, PNG output, the error exit in lib.rs).
set -euo pipefail
cd "$(dirname "$0")/../examples/src"
# A `#[cfg(test)]` module runs from its attribute to the file's end (where rustfmt
# and this project put it).
count() {
    for f in "$@"; do sed '/^#\[cfg(test)\]/,$d' "$f"; done | grep -v -E '^\s*$|^\s*//' | wc -l
}
tuff_shared=(gpu.rs render.rs headless.rs pipeline.rs cli.rs)
ash_shared=(raw_ash.rs)
echo "| Scene | tuff: scene + shared = total | raw ash: scene + shared = total | tuff / raw ash |"
echo "|---|---:|---:|---:|"
for scene in triangle teapots bezier; do
    t_scene=$(count "bin/$scene.rs" "scenes/$scene.rs")
    t_shared=$(count "${tuff_shared[@]}")
    a_scene=$(count "bin/${scene}_ash.rs")
    a_shared=$(count "${ash_shared[@]}")
    t=$((t_scene + t_shared))
    a=$((a_scene + a_shared))
    ratio=$(awk -v t="$t" -v a="$a" 'BEGIN { printf "%.2f", t / a }')
    echo "| $scene | $t_scene + $t_shared = **$t** | $a_scene + $a_shared = **$a** | $ratio |"
done
echo
echo "Files: tuff \`bin/<scene>.rs\`, \`scenes/<scene>.rs\` and ${tuff_shared[*]}; raw ash"
echo "\`bin/<scene>_ash.rs\` and ${ash_shared[*]}. With its window path (window.rs), the"
echo "tuff teapots take $(count bin/teapots.rs scenes/teapots.rs "${tuff_shared[@]}" window.rs) lines."
