#!/usr/bin/env bash
# tests/install/test_install: the library as a user gets it.
#
# Installs the build into a fresh temporary prefix (cmake --install), builds
# examples/*.c with nothing but the installed headers and pkg-config (shared
# library, and static library with `pkg-config --static`), and runs them:
# atlas_example on its own generated mesh and on a cubesphere OBJ written by
# the installed `scaf gen`; its output is then proved bijective by the
# installed `scaf check`. With PYTHON (an interpreter path, when it exists),
# the installed Python package is imported from the prefix alone (PYTHONPATH,
# no SCAF_LIBRARY), must load the installed libscaf.so, and runs
# examples/atlas_example.py on the cubesphere; its output is checked too.
# Exit 0 pass, 1 fail, 77 skip (no pkg-config).
#
# usage: test_install.sh BUILD_DIR SOURCE_DIR CC [EXTRA_CFLAGS [PYTHON]]
#        (PYTHON may also come from the environment variable SCAF_PYTHON)
set -euo pipefail
build="$1" src="$2" cc="$3" extra="${4:-}" python="${5:-${SCAF_PYTHON:-}}"
if ! command -v pkg-config >/dev/null; then
  # CI must run every test: a missing tool fails there (SCAF_REQUIRE_DATA)
  if [ -n "${SCAF_REQUIRE_DATA:-}" ] && [ "$SCAF_REQUIRE_DATA" != 0 ]; then
    echo "FAIL: pkg-config not found and SCAF_REQUIRE_DATA is set"
    exit 1
  fi
  echo "pkg-config not found: skipped"
  exit 77
fi
export OPENBLAS_NUM_THREADS=1
mkdir -p "$build/test-tmp"
tmp="$(mktemp -d "$build/test-tmp/install.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
pc="$(dirname "$(find "$tmp/prefix" -name scaf.pc | head -1)")"
export PKG_CONFIG_PATH="$pc"
libdir="$(pkg-config --variable=libdir scaf)"
test -f "$tmp/prefix/include/scaf/scaf.h" && test -f "$tmp/prefix/include/scaf/atlas.h"
test -x "$tmp/prefix/bin/scaf"
ls "$libdir"/libscaf.so.0 >/dev/null   # SOVERSION link
# the shared library exports the public API only (scaf_*, see SCAF_API)
if command -v nm >/dev/null; then
  other="$(nm -D --defined-only "$libdir/libscaf.so" | awk '{print $3}' | grep -v '^scaf_' | grep -v '^_\(_\|init\|fini\|edata\|end\)' || true)"
  [ -z "$other" ] || { echo "libscaf.so exports non-API symbols:"; echo "$other" | head; exit 1; }
  nm -D --defined-only "$libdir/libscaf.so" | grep ' scaf_atlas_get_uv$' >/dev/null
fi
"$tmp/prefix/bin/scaf" --version | grep -x "scaf $(pkg-config --modversion scaf)" >/dev/null
flags=(-std=c17 -Wall -Wextra -Wpedantic -Werror $extra)
for ex in atlas_example param_example; do
  # shared: the only include path and library come from pkg-config
  "$cc" "${flags[@]}" "$src/examples/$ex.c" $(pkg-config --cflags --libs scaf) -lm \
      -Wl,-rpath,"$libdir" -o "$tmp/$ex"
  # static: libscaf.a plus what `pkg-config --static` lists
  "$cc" "${flags[@]}" "$src/examples/$ex.c" $(pkg-config --cflags scaf) "$libdir/libscaf.a" \
      $(pkg-config --static --libs scaf | sed 's/ -lscaf / /') -lm -o "$tmp/$ex-static"
done
# CMake: a project with only find_package(scaf CONFIG REQUIRED), linking
# scaf::scaf (shared) and scaf::scaf_static
cmake -S "$src/tests/install/consumer" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$tmp/prefix" \
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER="$cc" -DCMAKE_C_FLAGS="$extra" \
      -DCMAKE_EXE_LINKER_FLAGS="$extra" >"$tmp/consumer.log" 2>&1 ||
  { cat "$tmp/consumer.log"; echo "find_package(scaf) failed"; exit 1; }
cmake --build "$tmp/consumer" >>"$tmp/consumer.log" 2>&1 || { cat "$tmp/consumer.log"; exit 1; }
for app in app_shared app_static; do
  "$tmp/consumer/$app" >"$tmp/$app.txt"
  grep -q "^scaf $(pkg-config --modversion scaf): E " "$tmp/$app.txt" || { cat "$tmp/$app.txt"; exit 1; }
done
# the shared app loads the installed library (the build tree's rpath is not used)
# (whole outputs captured: `ldd | grep -q` under pipefail fails at random
# when grep quits early and ldd dies of SIGPIPE)
shared_libs="$(ldd "$tmp/consumer/app_shared")"
static_libs="$(ldd "$tmp/consumer/app_static" || true)"
grep -qF "$tmp/prefix" <<<"$shared_libs" || { echo "$shared_libs"; exit 1; }
! grep -q libscaf <<<"$static_libs" || { echo "app_static loads libscaf.so"; exit 1; }
echo "cmake consumer: $(cat "$tmp/app_shared.txt") (shared), $(cat "$tmp/app_static.txt") (static)"
"$tmp/param_example" >"$tmp/param.txt"
"$tmp/param_example-static" >/dev/null
"$tmp/atlas_example" >"$tmp/atlas.txt"
"$tmp/atlas_example-static" >/dev/null
"$tmp/prefix/bin/scaf" gen cubesphere --size 5 -o "$tmp/cube.obj"
"$tmp/atlas_example" "$tmp/cube.obj" "$tmp/cube_atlas.obj" >"$tmp/cube.txt"
"$tmp/prefix/bin/scaf" check "$tmp/cube_atlas.obj" >"$tmp/check.txt"
grep -q "6 charts" "$tmp/cube.txt"
if [ -n "$python" ] && [ -x "$python" ]; then (
  # an ASan build's library needs its runtime preloaded into python
  source "$src/python/tests/sanitizer_env.sh"
  scaf_python_sanitizer_env "$libdir/libscaf.so" || exit 0
  # the installed package, found through PYTHONPATH only
  pyinit="$(find "$tmp/prefix" -path '*/scaf/_install_paths.py' | head -1)"
  [ -n "$pyinit" ] || { echo "the Python package was not installed"; exit 1; }
  pydir="$(dirname "$(dirname "$pyinit")")"
  env -u SCAF_LIBRARY PYTHONPATH="$pydir" PYTHONDONTWRITEBYTECODE=1 "$python" -c '
import os, sys, scaf
lib = os.path.realpath(scaf.library_path)
prefix = os.path.realpath(sys.argv[1]) + os.sep
assert lib.startswith(prefix), "loaded " + lib
assert os.path.realpath(scaf.__file__).startswith(prefix), "imported " + scaf.__file__
print("python: scaf", scaf.__version__, "from", scaf.__file__, "with", lib)' "$tmp/prefix"
  env -u SCAF_LIBRARY PYTHONPATH="$pydir" PYTHONDONTWRITEBYTECODE=1 "$python" \
      "$src/examples/atlas_example.py" "$tmp/cube.obj" "$tmp/cube_atlas_py.obj" >"$tmp/cube_py.txt"
  grep -q "6 charts" "$tmp/cube_py.txt"
  "$tmp/prefix/bin/scaf" check "$tmp/cube_atlas_py.obj" >/dev/null
  tail -n 1 "$tmp/cube_py.txt"
) fi
tail -n 1 "$tmp/param.txt"
tail -n 1 "$tmp/atlas.txt"
tail -n 1 "$tmp/cube.txt"
echo "installed scaf: examples built (shared + static) and run; scaf check: $(head -n 1 "$tmp/check.txt")"
