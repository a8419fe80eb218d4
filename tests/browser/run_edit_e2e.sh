#!/usr/bin/env bash
# tests/browser/run_edit_e2e.sh: the ctest browser/edit_e2e (label
# `browser`): runs edit_e2e.mjs with node and Debian's chromium.
#   run_edit_e2e.sh SCAF_BINARY WORK_DIR [SCRIPT]
# SCRIPT: edit_e2e.mjs (default) or edit_tools_e2e.mjs (the ctest
# browser/edit_tools_e2e: selection, pins, texture, 3D view, padding).
# Skips (exit 77, with the reason) only when node or chromium is not
# installed (scripts/setup.sh installs both), and fails instead under
# SCAF_REQUIRE_DATA (CI); fails when they are but playwright-core is not
# (scripts/setup.sh runs `npm ci` here).
# SCAF_CHROMIUM names another Chromium binary.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
scaf="$1"
work="$2"
script="${3:-edit_e2e.mjs}"
browser="${SCAF_CHROMIUM:-$(command -v chromium || true)}"
skip() { # the reason; a failure where every test must run (CI)
  if [ -n "${SCAF_REQUIRE_DATA:-}" ] && [ "$SCAF_REQUIRE_DATA" != 0 ]; then
    echo "FAIL: $1 and SCAF_REQUIRE_DATA is set"
    exit 1
  fi
  echo "SKIP: $1"
  exit 77
}
if ! command -v node >/dev/null; then skip "node is not installed (scripts/setup.sh installs it)"; fi
if [ -z "$browser" ] || [ ! -x "$browser" ]; then
  skip "chromium is not installed (scripts/setup.sh installs it)"
fi
if [ ! -f "$here/node_modules/playwright-core/package.json" ]; then
  echo "FAIL: playwright-core is missing: run \`npm ci\` in $here (scripts/setup.sh does)"
  exit 1
fi
exec node "$here/$script" "$scaf" "$work" "$browser"
