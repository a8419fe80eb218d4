"""scaf_uv.checker: the library's exact bijectivity verdict on a UV map.

Neither the C API nor the Python package exposes the checker
(geom/bijectivity) yet, so Check runs the `scaf` program: it writes the
triangulated mesh with its UVs to a temporary OBJ (doubles printed with
repr, which reads back bit for bit) and parses `scaf check --json`. Which
triangles are flipped or degenerate, and whose boundaries cross or touch,
is decided in the add-on, exactly (scaf_uv.orientation, scaf_uv.overlaps),
so they can be selected; the verdict and every count come from the
program.
Fails with CheckError naming the program and its message.
"""

import json
import os
import shutil
import subprocess
import tempfile


class CheckError(Exception):
    pass


def find_program(preferred, library_path):
    """The scaf program: the add-on preference, else `scaf` on PATH, else
    beside the loaded libscaf (a build tree: build/scaf; an install:
    <prefix>/bin/scaf). None when there is none."""
    if preferred:
        return preferred if os.access(preferred, os.X_OK) else None
    found = shutil.which("scaf")
    if found:
        return found
    if library_path:
        d = os.path.dirname(os.path.realpath(library_path))
        for p in (os.path.join(d, "scaf"), os.path.join(d, "..", "bin", "scaf")):
            if os.path.isfile(p) and os.access(p, os.X_OK):
                return os.path.normpath(p)
    return None


def write_obj(path, V, F, UV, FT):
    """OBJ with v, vt and f v/vt (1-based); every number as repr(float)."""
    with open(path, "w") as out:
        out.writelines("v %r %r %r\n" % (float(x), float(y), float(z)) for x, y, z in V)
        out.writelines("vt %r %r\n" % (float(u), float(v)) for u, v in UV)
        out.writelines("f %d/%d %d/%d %d/%d\n" % (f[0] + 1, t[0] + 1, f[1] + 1, t[1] + 1, f[2] + 1, t[2] + 1)
                       for f, t in zip(F.tolist(), FT.tolist()))


def check(program, V, F, UV, FT):
    """`scaf check --json` on the map: the parsed report (dict with
    bijective, flipped, boundary_crossings, min_chart_gap, ...)."""
    with tempfile.TemporaryDirectory(prefix="scaf_uv_") as tmp:
        obj = os.path.join(tmp, "check.obj")
        write_obj(obj, V, F, UV, FT)
        p = subprocess.run([program, "check", "--json", obj], capture_output=True, text=True)
    if p.returncode not in (0, 1):  # 0 bijective, 1 not bijective
        raise CheckError("%s check failed (exit %d): %s" % (program, p.returncode, p.stderr.strip()))
    try:
        return json.loads(p.stdout)
    except ValueError:
        raise CheckError("%s check: unexpected output %r" % (program, p.stdout[:200]))


OVERLAP_KEYS = ("boundary_crossings", "boundary_touchings", "boundary_foldbacks", "folded_edges",
                "nonmanifold_edges", "nested_loops", "corner_overlaps")


def summary(report):
    """"not bijective: flipped 3, boundary_crossings 2" or "bijective"."""
    if report.get("bijective"):
        return "bijective"
    bad = ["%s %s" % (k, report[k]) for k in ("flipped", "degenerate") + OVERLAP_KEYS if report.get(k)]
    return "not bijective: " + ", ".join(bad)
