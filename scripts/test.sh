#!/usr/bin/env bash
# The whole test suite, as CI runs it:
#   1. AddressSanitizer + UndefinedBehaviorSanitizer build, all tests;
#   2. bounded fuzz smoke run of every fuzz target (clang libFuzzer);
#   3. Release build; the layering check (scripts/check_layers.sh) on its
#      objects: no include or call goes up base -> geom -> mesh -> opt ->
#      scaffold -> app -> tools; the format check (scripts/check_format.sh,
#      .clang-format); then all tests (ctest's summary closes the output).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="$(nproc)"
export OPENBLAS_NUM_THREADS=1   # deterministic, and the sanitizers prefer it

echo "== sanitizer build (ASan + UBSan) =="
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DSCAF_SANITIZE=ON -DSCAF_BENCH=OFF >/dev/null
cmake --build build-asan -j"$jobs"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-asan --output-on-failure -j"$jobs"

if [ -x scripts/fuzz_smoke.sh ] || [ -f scripts/fuzz_smoke.sh ]; then
  echo "== fuzz smoke =="
  bash scripts/fuzz_smoke.sh
fi

echo "== release build =="
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$jobs"
echo "== layering and format =="
bash scripts/check_layers.sh --build build
bash scripts/check_format.sh
ctest --test-dir build --output-on-failure -j"$jobs"

