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
#   tools     the program stands on the public API (include/scaf/), base/,
#             mesh/ (its I/O) and app/: a tools/ file that includes
#             scaffold/, opt/ or geom/ is a violation unless it is on the
#             commented allow-list TOOLS_INTERNAL_ALLOWED below (which
#             should only shrink); an allow-listed file that no longer
#             includes any of them is reported too, to be struck off;
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

# ---- tools/ on the public API (issue 31, item 4) ---------------------------
INTERNAL = ("scaffold", "opt", "geom")
# tools/ files that still include scaffold/, opt/ or geom/, and why. The
# goal is an empty list: move the work behind include/scaf/ and strike the
# file off.
TOOLS_INTERNAL_ALLOWED = {
    # the 2D verdict and gap (geom/bijectivity's bij_report, geom/chart_gap)
    # that `scaf check`, `param` and `atlas` print: the public API has no UV
    # check that returns these counts yet
    "tools/cmd_check.c": "2D bijectivity report",
    "tools/cmd_param.c": "2D bijectivity report, chart gap",
    "tools/cmd_atlas.c": "2D bijectivity report, chart gap",
    # `scaf deform` (2D handles): its progress reads the handle term's error
    # and checks each iteration with geom/bijectivity
    "tools/cmd_deform.c": "handle error (opt/handle_term), 2D bijectivity",
    # the glTF primitive table on the terminal labels the output's charts
    # with geom/chart_gap's chart_gap_labels (no public chart labelling yet)
    "tools/cli_mesh_io.c": "chart labels of a glTF output",
}
tools_internal = set()
for dirpath, _, files in os.walk(os.path.join(root, "tools")):
    for name in sorted(files):
        if not name.endswith((".c", ".h")):
            continue
        path = os.path.join(dirpath, name)
        rel = os.path.relpath(path, root).replace(os.sep, "/")
        with open(path, encoding="utf-8", errors="replace") as f:
            for lineno, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m or m.group(1) not in INTERNAL:
                    continue
                tools_internal.add(rel)
                if rel not in TOOLS_INTERNAL_ALLOWED:
                    violations.append(
                        f"{rel}:{lineno}: includes {line.strip()[len('#include '):].strip()} "
                        f"({m.group(1)}), but tools/ stands on the public API (include/scaf/), "
                        f"base, mesh and app (or the allow-list in scripts/check_layers.sh)")
for rel in sorted(TOOLS_INTERNAL_ALLOWED):
    if rel not in tools_internal and os.path.exists(os.path.join(root, rel)):
        violations.append(f"{rel}: allow-listed for scaffold/opt/geom includes but has none: "
                          f"strike it off TOOLS_INTERNAL_ALLOWED")

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
