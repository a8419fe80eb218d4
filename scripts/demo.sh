#!/usr/bin/env bash
# The main job on a built-in example (README's first command): generate a
# bumpy open hemisphere, compute its bijective UV map with SCAF, prove it
# bijective with the independent checker, and draw it.
#   out/hemisphere.obj         the generated surface (no UVs)
#   out/hemisphere_uv.obj      the same mesh with vt + f v/vt
#   out/hemisphere_uv.svg      the UV layout shaded by distortion (+ scaffold)
#   out/hemisphere_report.json energy and time per iteration, phase split
#   out/hemisphere_uv.png      the same as a PNG with a 3D checkerboard
#   out/cubesphere_atlas.obj   a 6-chart texture atlas (4 texels of padding
#                              at 1024), proved bijective, and its PNG
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/scaf --version
./build/scaf gen hemisphere --size 24 -o out/hemisphere.obj
./build/scaf param out/hemisphere.obj -o out/hemisphere_uv.obj --iterations 30 --verify \
    --svg out/hemisphere_uv.svg --svg-scaffold --report out/hemisphere_report.json \
    --png out/hemisphere_uv.png --png-size 512 --checker
./build/scaf check out/hemisphere_uv.obj
./build/scaf gen cubesphere --size 12 -o out/cubesphere.obj
./build/scaf atlas out/cubesphere.obj -o out/cubesphere_atlas.obj --resolution 1024 --padding-texels 4 \
    --png out/cubesphere_atlas.png --png-size 1024 --checker
./build/scaf check out/cubesphere_atlas.obj
echo "wrote out/hemisphere_uv.obj (pictures out/hemisphere_uv.svg, .png) and the atlas" \
    "out/cubesphere_atlas.obj (picture out/cubesphere_atlas.png)"
