#!/usr/bin/env bash
# The main job on a built-in example (README's first command): generate a
# bumpy open hemisphere, compute its bijective UV map with SCAF, prove it
# bijective with the independent checker, and draw it.
#   out/hemisphere.obj         the generated surface (no UVs)
#   out/hemisphere_uv.obj      the same mesh with vt + f v/vt
#   out/hemisphere_uv.svg      the UV layout shaded by distortion (+ scaffold)
#   out/hemisphere_report.json energy and time per iteration, phase split
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/scaf --version
./build/scaf gen hemisphere --size 24 -o out/hemisphere.obj
./build/scaf param out/hemisphere.obj -o out/hemisphere_uv.obj --iterations 30 --verify \
    --svg out/hemisphere_uv.svg --svg-scaffold --report out/hemisphere_report.json
./build/scaf check out/hemisphere_uv.obj
echo "wrote out/hemisphere_uv.obj and the picture out/hemisphere_uv.svg"
