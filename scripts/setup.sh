#!/usr/bin/env bash
# Install every Debian package scaf needs to build, test, fuzz and benchmark.
# Works as root on a fresh Debian 12; uses sudo otherwise. Also installs the
# npm packages of tests/browser (npm ci).
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PACKAGES=(
  build-essential cmake pkg-config clang clang-format   # clang-format: style check (scripts/check_format.sh)
  libsuitesparse-dev libopenblas-dev libmetis-dev   # CHOLMOD analysis, UMFPACK sparse LU; OpenBLAS: libblas.so
  zlib1g-dev                                        # .gz input
  libpng-dev                                        # PNG pictures
  libcmocka-dev                                     # tests
  libgmp-dev                                        # tests: exact rational reference
  libtet1.5-dev g++                                 # TetGen (AGPL-3.0+): the initial 3D scaffold
  libtinygltf-dev                                   # glTF 2.0 in and out (src/mesh/gltf_io.cpp; MIT)
  tetgen                                            # tests/checks: `tetgen -d`, an independent self-intersection check
  valgrind                                          # bench: instruction counts
  python3 python3-numpy                             # the Python package and its tests
  python3-jsonschema                                # tests/docs/test_report_schemas: reports against docs/schemas
  python3-meshio                                    # python tests + examples/volume_example.py: a meshio mesh into scaf.inflate (python3-trimesh is not in Debian 12)
  python3-setuptools python3-wheel python3-build python3-venv python3-pip  # pip install . offline (tests/install/test_pip.sh)
  libmicrohttpd-dev                                 # `scaf edit`: the local HTTP server
  chromium nodejs                                   # tests/browser: `scaf edit` in headless Chromium
  libjs-three                                       # `scaf edit`'s 3D view: three.js (r111) embedded at build time (optional: without it the page says the view is unavailable)
  blender                                           # tests/blender: the add-on (integrations/blender) run headless
  xvfb xauth                                        # tests/blender: the add-on's modal run in a window (xvfb-run)
)
missing=()
for p in "${PACKAGES[@]}"; do
  [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" = "install ok installed" ] || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# npm: part of some nodejs builds (NodeSource), a package of its own in Debian
if ! command -v npm >/dev/null; then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends npm
fi
# tests/browser drives the system's Chromium with playwright-core (exact
# versions of package-lock.json; no browser is downloaded)
(cd "$(dirname "$0")/../tests/browser" && npm ci --no-audit --no-fund --loglevel=error)
