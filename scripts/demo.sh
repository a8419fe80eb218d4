#!/usr/bin/env bash
# The main job on a built-in example (README's first command).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/scaf --version
