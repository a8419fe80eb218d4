#!/usr/bin/env bash
# The layering of the house (DESIGN.md): base -> geom -> mesh -> opt ->
# scaffold -> app -> tools; a layer may use itself and the layers before it,
# never one after it.
#
#   scripts/check_layers.sh [--build DIR] [ROOT]
#
# Checks, in ROOT (default: this repository):
#   includes  every `#include "layer/..."` in src/<layer>/ and tools/
#             (the public headers "scaf/..." belong to no layer);
#   calls     with --build DIR (a configured and built CMake tree): every
#             function or variable an object file of src/<layer>/ or tools/
#             uses (nm: undefined symbols) that another object of the
#             library defines in a later layer -- this catches calls through
#             the public header scaf/scaf.h, which the include check cannot.
# Prints one line per violation (file, what, which layers) and exits 1 if
# there is any, 0 otherwise; 2 on bad usage.
set -euo pipefail

build=""
root=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="${2:?--build needs a directory}"; shift 2 ;;
    -h|--help) sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "check_layers: unknown option '$1'" >&2; exit 2 ;;
    *) root="$1"; shift ;;
  esac
done
[ -n "$root" ] || root="$(cd "$(dirname "$0")/.." && pwd)"
if [ ! -d "$root/src" ]; then
  echo "check_layers: $root has no src/ folder" >&2
  exit 2
fi
if [ -n "$build" ] && [ ! -d "$build" ]; then
  echo "check_layers: build folder $build does not exist" >&2
  exit 2
fi

exec python3 - "$root" "$build" <<'PY'
import os, re, subprocess, sys

root, build = sys.argv[1], sys.argv[2]
LAYERS = ["base", "geom", "mesh", "opt", "scaffold", "app", "tools"]
RANK = {name: i for i, name in enumerate(LAYERS)}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([A-Za-z_]+)/')
violations = []

def layer_of(rel):
    """Layer of a path relative to root (src/<layer>/... or tools/...)."""
    parts = rel.split(os.sep)
    if parts[0] == "tools":
        return "tools"
    if parts[0] == "src" and len(parts) > 2 and parts[1] in RANK:
        return parts[1]
    return None

def may_use(user):
    return ", ".join(LAYERS[: RANK[user] + 1])

# ---- includes -------------------------------------------------------------
for top in ("src", "tools"):
    for dirpath, _, files in os.walk(os.path.join(root, top)):
        for name in sorted(files):
            if not name.endswith((".c", ".h")):
                continue
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, root)
            user = layer_of(rel)
            if user is None:
                continue
            with open(path, encoding="utf-8", errors="replace") as f:
                for lineno, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if m and m.group(1) in RANK and RANK[m.group(1)] > RANK[user]:
                        violations.append(
                            f"{rel}:{lineno}: includes {line.strip()[len('#include '):].strip()} "
                            f"({m.group(1)}), but {user} may use only {may_use(user)}")

# ---- calls (symbols of the built objects) ---------------------------------
if build:
    objects = {}  # object path -> (source rel path, layer)
    for dirpath, _, files in os.walk(build):
        for name in files:
            if not name.endswith(".o"):
                continue
            path = os.path.join(dirpath, name)
            norm = path.replace(os.sep, "/")
            m = re.search(r"/(src/([a-z_]+)/[^/]+\.c)\.o$", norm) or re.search(r"/(tools/[^/]+\.c)\.o$", norm)
            if not m:
                continue
            rel = m.group(1)
            lay = layer_of(rel.replace("/", os.sep))
            if lay is not None and (("scaf_obj.dir" in norm) or lay == "tools"):
                objects[path] = (rel, lay)
    if not objects:
        print(f"check_layers: no object files of src/ or tools/ under {build}: build it first", file=sys.stderr)
        sys.exit(2)
    defined, used = {}, {}
    for path, (rel, lay) in sorted(objects.items()):
        out = subprocess.run(["nm", "-P", path], capture_output=True, text=True, check=True).stdout
        for line in out.splitlines():
            f = line.split()
            if len(f) < 2:
                continue
            sym, kind = f[0], f[1]
            if kind in ("U", "w", "v"):
                used.setdefault(path, set()).add(sym)
            elif kind.isupper():
                defined.setdefault(sym, (rel, lay))
    for path, syms in sorted(used.items()):
        rel, lay = objects[path]
        for sym in sorted(syms):
            if sym in defined:
                drel, dlay = defined[sym]
                if RANK[dlay] > RANK[lay]:
                    violations.append(f"{rel}: uses {sym} (defined in {drel}, {dlay}), "
                                      f"but {lay} may use only {may_use(lay)}")

for v in violations:
    print(v)
checked = "includes and calls" if build else "includes (no --build: calls not checked)"
if violations:
    print(f"check_layers: {len(violations)} upward dependencies ({checked})", file=sys.stderr)
    sys.exit(1)
print(f"check_layers: no upward dependency ({checked})")
PY
