#!/usr/bin/env bash
# python/tests/run_tests.sh: the ctest python/test_python.
#
# Runs the unittest suite python/tests/test_*.py with the given interpreter
# (the Debian /usr/bin/python3 by default, whose numpy is python3-numpy)
# against the build's libscaf.so (SCAF_LIBRARY, set by ctest with
# SCAF_BINARY, SCAF_LAYOUT_PROGRAM, SCAF_TEST_TMPDIR). When libscaf.so is
# sanitizer-instrumented (SCAF_SANITIZE=ON), the interpreter is not, so the
# sanitizer runtimes the library links are preloaded (LD_PRELOAD) and leak
# detection is off: the leaks LeakSanitizer would report are the
# interpreter's own at exit (the C tests check the library's leaks). The
# suite runs twice: as is (with numpy when installed), then with numpy
# hidden (`import numpy` fails), which is the package's list-only mode. Exit 0
# pass, 1 fail, 77 skip (no interpreter, or an instrumented library whose
# runtimes cannot be preloaded, e.g. clang's static ASan runtime).
#
# usage: run_tests.sh PYTHON PYTHON_SOURCE_DIR
set -euo pipefail
py="$1" dir="$2"
if [ ! -x "$py" ]; then
  # CI must run every test: there a missing interpreter fails (SCAF_REQUIRE_DATA)
  if [ -n "${SCAF_REQUIRE_DATA:-}" ] && [ "$SCAF_REQUIRE_DATA" != 0 ]; then
    echo "FAIL: $py not found and SCAF_REQUIRE_DATA is set"
    exit 1
  fi
  echo "$py not found: skipped"
  exit 77
fi
source "$dir/tests/sanitizer_env.sh"
scaf_python_sanitizer_env "$SCAF_LIBRARY" || exit 77
export PYTHONPATH="$dir${PYTHONPATH:+:$PYTHONPATH}"
export PYTHONDONTWRITEBYTECODE=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$SCAF_TEST_TMPDIR"
"$py" -m unittest discover -s "$dir/tests" -p 'test_*.py' -v
echo "== again without numpy (lists in, lists out) =="
exec "$py" -c "
import sys
sys.modules['numpy'] = None  # import numpy now raises ImportError
import unittest
unittest.main(module=None, argv=['unittest', 'discover', '-s', sys.argv[1], '-p', 'test_*.py'])" "$dir/tests"
