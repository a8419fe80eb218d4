#!/usr/bin/env bash
# SCAF_REQUIRE_DATA turns a skip for missing test data into a failure (CI
# sets it, so a run without ../shared/data cannot pass with tests unrun).
# Runs a test program that reads seams/spot.obj with SCAF_DATA_DIR pointing
# at an empty folder: it must pass (skipping) without the variable, and
# fail, naming the file, with it.
#   test_require_data.sh TEST_PROGRAM
set -euo pipefail
prog="$1"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

SCAF_REQUIRE_DATA=0 SCAF_DATA_DIR="$tmp" "$prog" >"$tmp/skip.out" 2>&1 ||
  fail "without SCAF_REQUIRE_DATA a missing file must skip: $(cat "$tmp/skip.out")"
grep -q "skipped" "$tmp/skip.out" || fail "no skip was reported: $(cat "$tmp/skip.out")"

if SCAF_REQUIRE_DATA=1 SCAF_DATA_DIR="$tmp" "$prog" >"$tmp/req.out" 2>&1; then
  fail "with SCAF_REQUIRE_DATA=1 a missing file must fail the test"
fi
grep -q "seams/spot.obj is missing and SCAF_REQUIRE_DATA is set" "$tmp/req.out" ||
  fail "the failure does not name the file: $(cat "$tmp/req.out")"
echo "ok"
