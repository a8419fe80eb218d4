#!/usr/bin/env bash
# tests/blender/run_blender_test.sh: the ctest blender/addon (label
# `blender`): the add-on zip (integrations/blender/make_zip.py) installed
# into a scratch Blender user folder and run headless by test_addon.py
# against this build (PYTHONPATH: the checkout's python/, SCAF_LIBRARY:
# the build's libscaf.so, the build's scaf program for scaf check).
#   run_blender_test.sh SOURCE_DIR SCAF_PROGRAM LIBSCAF WORK_DIR
# Skips (exit 77) only when Blender is not installed (scripts/setup.sh
# installs Debian's), and fails instead under SCAF_REQUIRE_DATA (CI).
# SCAF_BLENDER names another Blender binary.
set -euo pipefail
src="$1" scaf="$(realpath "$2")" lib="$(realpath "$3")" work="$4"
blender="${SCAF_BLENDER:-$(command -v blender || true)}"
if [ -z "$blender" ] || [ ! -x "$blender" ]; then
  if [ -n "${SCAF_REQUIRE_DATA:-}" ] && [ "$SCAF_REQUIRE_DATA" != 0 ]; then
    echo "FAIL: blender is not installed and SCAF_REQUIRE_DATA is set"
    exit 1
  fi
  echo "SKIP: blender is not installed (scripts/setup.sh installs it)"
  exit 77
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
exec "$blender" -b --factory-startup --python-exit-code 1 \
  --python "$src/tests/blender/test_addon.py" -- "$work/scaf_uv.zip" "$scaf" "$work"
