#!/usr/bin/env bash
# tests/blender/run_blender_test.sh: the ctest blender/addon (label
# `blender`): the add-on zip (integrations/blender/make_zip.py) installed
# into a scratch Blender user folder and run headless by test_addon.py
# against this build (PYTHONPATH: the checkout's python/, SCAF_LIBRARY:
# the build's libscaf.so, the build's scaf program for scaf check), then
# test_modal.py in a window under xvfb-run (the operator as a click runs
# it: modal, worker thread, the UI's undo step).
#   run_blender_test.sh SOURCE_DIR SCAF_PROGRAM LIBSCAF WORK_DIR
# Skips (exit 77) only when Blender or xvfb-run is not installed
# (scripts/setup.sh installs both), and fails instead under
# SCAF_REQUIRE_DATA (CI).
# SCAF_BLENDER names another Blender binary.
set -euo pipefail
src="$1" scaf="$(realpath "$2")" lib="$(realpath "$3")" work="$4"
blender="${SCAF_BLENDER:-$(command -v blender || true)}"
skip() { # the reason; a failure where every test must run (CI)
  if [ -n "${SCAF_REQUIRE_DATA:-}" ] && [ "$SCAF_REQUIRE_DATA" != 0 ]; then
    echo "FAIL: $1 and SCAF_REQUIRE_DATA is set"
    exit 1
  fi
  echo "SKIP: $1"
  exit 77
}
if [ -z "$blender" ] || [ ! -x "$blender" ]; then
  skip "blender is not installed (scripts/setup.sh installs it)"
fi
# a sanitizer build's libscaf needs its runtime preloaded into Blender
source "$src/python/tests/sanitizer_env.sh"
scaf_python_sanitizer_env "$lib" || exit 77
rm -rf "$work"
mkdir -p "$work/user_scripts" "$work/user_config"
python3 "$src/integrations/blender/make_zip.py" "$work/scaf_uv.zip"
export BLENDER_USER_SCRIPTS="$work/user_scripts" BLENDER_USER_CONFIG="$work/user_config"
export PYTHONPATH="$src/python${PYTHONPATH:+:$PYTHONPATH}" SCAF_LIBRARY="$lib"
export OPENBLAS_NUM_THREADS=1 PYTHONDONTWRITEBYTECODE=1
"$blender" -b --factory-startup --python-exit-code 1 \
  --python "$src/tests/blender/test_addon.py" -- "$work/scaf_uv.zip" "$scaf" "$work"
# the modal operator as a click runs it needs a window: Xvfb gives one
if ! command -v xvfb-run >/dev/null || ! command -v xauth >/dev/null; then
  skip "xvfb-run (Debian xvfb, xauth) is not installed: the modal run is untested"
fi
rm -f "$work/modal.txt"
timeout 300 xvfb-run -a -s "-screen 0 1280x800x24" "$blender" --factory-startup --enable-event-simulate \
  --window-geometry 0 0 1280 800 --python "$src/tests/blender/test_modal.py" -- "$work" || true
result="$(cat "$work/modal.txt" 2>/dev/null || echo "no result: Blender ended before writing it")"
echo "modal run: $result"
[ "$result" = ok ]
