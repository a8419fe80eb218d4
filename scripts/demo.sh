#!/usr/bin/env bash
# The main job on a built-in example (README's first command). Until the
# optimizer exists: generate the sample meshes and print their topology.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/scaf --version
./build/scaf gen hemisphere --size 24 -o out/hemisphere.obj
./build/scaf info out/hemisphere.obj
./build/scaf gen holes -o out/holes.obj
./build/scaf info out/holes.obj
./build/scaf gen cubesphere -o out/cubesphere.obj
./build/scaf info --json out/cubesphere.obj
