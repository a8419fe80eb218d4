#!/usr/bin/env bash
# The pictures at the top of README.md, made by scaf itself: automatic
# charts of the Stanford bunny (3D, then the packed atlas with a checker
# on the surface) and a sphere whose cap passes through its bottom, pulled
# free of self-intersections by `scaf untangle`.
# usage: bash scripts/readme_pictures.sh [BUNNY.obj]
#        (default: closed/bunny.obj of the shared test meshes beside the checkout)
set -euo pipefail
cd "$(dirname "$0")/.."
bunny="${1:-${SCAF_DATA_DIR:-../shared/data}/closed/bunny.obj}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
./build/scaf atlas "$bunny" -o "$tmp/bunny_atlas.obj" --png docs/bunny-atlas.png --png-size 400 \
    --checker --png-seams docs/bunny-seams.png --quiet
./build/scaf gen dented -o "$tmp/dented.obj"
./build/scaf untangle "$tmp/dented.obj" -o "$tmp/untangled.obj" --png docs/dented-untangle.png \
    --png-size 300 --quiet
echo "wrote docs/bunny-seams.png, docs/bunny-atlas.png, docs/dented-untangle.png"
