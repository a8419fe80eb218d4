#!/usr/bin/env bash
# Install every Debian package scaf needs to build, test, fuzz and benchmark.
# Works as root on a fresh Debian 12; uses sudo otherwise.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PACKAGES=(
  build-essential cmake pkg-config clang clang-format   # clang-format: style check (scripts/check_format.sh)
  libsuitesparse-dev libopenblas-dev libmetis-dev   # CHOLMOD sparse Cholesky, UMFPACK sparse LU
  zlib1g-dev                                        # .gz input
  libpng-dev                                        # PNG pictures
  libcmocka-dev                                     # tests
  libgmp-dev                                        # tests: exact rational reference
  libtet1.5-dev g++                                 # TetGen (AGPL-3.0+): the initial 3D scaffold
  tetgen                                            # tests/checks: `tetgen -d`, an independent self-intersection check
  valgrind                                          # bench: instruction counts
  python3 python3-numpy                             # the Python package and its tests
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
