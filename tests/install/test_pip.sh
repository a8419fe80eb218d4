#!/usr/bin/env bash
# tests/install/test_pip: the Python package as a pip user gets it, offline.
#
# In a copy of the checkout's tracked files (a fresh clone, as far as the
# build can tell):
#   1. `python3 -m build --no-isolation --wheel` builds a wheel (setup.py runs
#      CMake for libscaf and puts it inside the package);
#   2. the wheel goes into a fresh virtual environment without the system's
#      packages (`pip install --no-index`): the package imports with no
#      environment variable, loads the libscaf inside it, has the program's
#      version, and passes python/tests from outside the source tree (lists
#      in and out: that environment has no numpy);
#   3. `pip install --no-build-isolation .` into a fresh environment that
#      sees the system's packages (Debian's numpy, setuptools, wheel) passes
#      the same suite with numpy.
# Exit 0 pass, 1 fail, 77 skip (no venv/build module; fails instead under
# SCAF_REQUIRE_DATA).
#
# usage: test_pip.sh SOURCE_DIR PYTHON SCAF_BINARY
set -euo pipefail
src="$1" py="$2" scaf="$3"
skip() {
  if [ -n "${SCAF_REQUIRE_DATA:-}" ] && [ "$SCAF_REQUIRE_DATA" != 0 ]; then
    echo "FAIL: $1 and SCAF_REQUIRE_DATA is set"
    exit 1
  fi
  echo "SKIP: $1"
  exit 77
}
"$py" -c 'import venv, ensurepip' 2>/dev/null || skip "$py has no venv/ensurepip (Debian: python3-venv)"
"$py" -c 'import build, setuptools, wheel' 2>/dev/null ||
  skip "$py lacks build/setuptools/wheel (Debian: python3-build python3-setuptools python3-wheel)"
export OPENBLAS_NUM_THREADS=1 PYTHONDONTWRITEBYTECODE=1
unset SCAF_LIBRARY PYTHONPATH
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# ---- a copy of the tracked files --------------------------------------
mkdir "$tmp/checkout"
if git -C "$src" rev-parse --git-dir >/dev/null 2>&1; then
  git -C "$src" ls-files -z --cached --others --exclude-standard |
    (cd "$src" && xargs -0 cp --parents -t "$tmp/checkout" 2>/dev/null || true)
else
  cp -r "$src/." "$tmp/checkout/"
  rm -rf "$tmp/checkout"/build*
fi
test -f "$tmp/checkout/pyproject.toml" || { echo "FAIL: no pyproject.toml in the copy"; exit 1; }

# ---- 1. the wheel ---------------------------------------------------------
(cd "$tmp/checkout" && "$py" -m build --no-isolation --wheel --outdir "$tmp/dist" >"$tmp/build.log" 2>&1) ||
  { tail -30 "$tmp/build.log"; echo "FAIL: building the wheel"; exit 1; }
wheel="$(ls "$tmp"/dist/scaf-*.whl)"
want="$("$scaf" --version | awk '{print $2}')"
case "$(basename "$wheel")" in
  "scaf-$want-"*linux*.whl) ;;
  *) echo "FAIL: wheel $(basename "$wheel"): not scaf-$want for this platform"; exit 1 ;;
esac

check_env() { # python of an environment, what it must import from
  (cd "$tmp" && "$1" - "$want" <<'PY'
import os, sys, scaf
want = sys.argv[1]
site = os.path.realpath(os.path.dirname(scaf.__file__))
lib = os.path.realpath(scaf.library_path)
assert sys.prefix != sys.base_prefix, "not in a virtual environment"
assert site.startswith(os.path.realpath(sys.prefix)), "imported " + scaf.__file__
assert os.path.dirname(lib) == site, "loaded " + lib + ", not the package's own library"
assert scaf.__version__ == want, scaf.__version__ + " != " + want
print("scaf", scaf.__version__, "from", site)
PY
  )
}

# ---- 2. the wheel into a bare environment --------------------------------
"$py" -m venv "$tmp/bare"
"$tmp/bare/bin/python" -m pip install --no-index --quiet "$wheel"
check_env "$tmp/bare/bin/python"
! "$tmp/bare/bin/python" -c 'import numpy' 2>/dev/null || echo "note: the bare environment has numpy"
(cd "$tmp" && SCAF_BINARY="$scaf" SCAF_TEST_TMPDIR="$tmp" \
  "$tmp/bare/bin/python" -m unittest discover -s "$tmp/checkout/python/tests" -p 'test_*.py' >"$tmp/bare.log" 2>&1) ||
  { tail -30 "$tmp/bare.log"; echo "FAIL: python/tests with the wheel"; exit 1; }
echo "wheel: $(tail -n 1 "$tmp/bare.log")"

# ---- 3. pip install . -------------------------------------------------
"$py" -m venv --system-site-packages "$tmp/site"
(cd "$tmp/checkout" && "$tmp/site/bin/python" -m pip install --no-build-isolation --no-index --quiet . \
  >"$tmp/pip.log" 2>&1) || { tail -30 "$tmp/pip.log"; echo "FAIL: pip install ."; exit 1; }
check_env "$tmp/site/bin/python"
(cd "$tmp" && SCAF_BINARY="$scaf" SCAF_TEST_TMPDIR="$tmp" \
  "$tmp/site/bin/python" -m unittest discover -s "$tmp/checkout/python/tests" -p 'test_*.py' >"$tmp/site.log" 2>&1) ||
  { tail -30 "$tmp/site.log"; echo "FAIL: python/tests after pip install ."; exit 1; }
"$tmp/site/bin/python" -c 'import numpy' || { echo "FAIL: numpy not visible"; exit 1; }
echo "pip install .: $(tail -n 1 "$tmp/site.log")"
