"""bench/paper/common: what every figure script of bench/paper shares.

The scripts remake the figures and Table 1 of Jiang, Schaefer, Panozzo,
"Simplicial Complex Augmentation Framework for Bijective Maps" (2017) with
the built `scaf` program (and, where only the API can do it, the Python
package python/scaf on the built libscaf.so). Each script writes its
pictures and one JSON record (fig<N>.json: what the paper shows, what scaf
measured, the claims checked, its Table 1 rows) into the output folder and
prints one line per claim; run_all.py turns the records into docs/paper.md.

Meshes come only from the shared folder of public meshes (SCAF_DATA_DIR,
else <repo>/../shared/data, as the tests find it) or are generated (`scaf
gen`, bench/subdivide.py). A missing mesh is a clean skip (a line saying
so, a record marked skipped), except under SCAF_REQUIRE_DATA=1 where it is
a failure, as in the tests. Every scaf command runs on one thread
(--threads 1, OPENBLAS_NUM_THREADS=1): the timings are one run on one
thread of whatever machine runs it.

Stdlib only (numpy is not needed): the Python package works with lists.
"""

import json
import math
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Commands that take --threads (the others run on one thread anyway).
THREADED = {"param", "atlas", "deform", "inflate"}


def scaf_binary():
    return os.environ.get("SCAF_BINARY") or os.path.join(ROOT, "build", "scaf")


def scaf_library():
    return os.environ.get("SCAF_LIBRARY") or os.path.join(ROOT, "build", "libscaf.so")


def data_dir():
    return os.environ.get("SCAF_DATA_DIR") or os.path.join(os.path.dirname(ROOT), "shared", "data")


def data_required():
    v = os.environ.get("SCAF_REQUIRE_DATA", "")
    return v not in ("", "0")


def child_env():
    """The environment of a scaf child: one BLAS thread; without the
    sanitizer preload the Python side may need (test_fast.sh sets it)."""
    env = dict(os.environ)
    env["OPENBLAS_NUM_THREADS"] = "1"
    if "SCAF_PAPER_CHILD_LD_PRELOAD" in env:
        env["LD_PRELOAD"] = env["SCAF_PAPER_CHILD_LD_PRELOAD"]
        if not env["LD_PRELOAD"]:
            del env["LD_PRELOAD"]
    if "SCAF_PAPER_CHILD_ASAN_OPTIONS" in env:
        env["ASAN_OPTIONS"] = env["SCAF_PAPER_CHILD_ASAN_OPTIONS"]
    return env


def import_scaf():
    """The Python package on the built library, one thread."""
    os.environ.setdefault("SCAF_LIBRARY", scaf_library())
    os.environ["OPENBLAS_NUM_THREADS"] = "1"
    sys.path.insert(0, os.path.join(ROOT, "python"))
    import scaf  # noqa: E402
    scaf.set_threads(1)
    return scaf


class Skip(Exception):
    """A mesh (or tool) the figure needs is absent."""


class Figure:
    """One figure's record: pictures, numbers, claims, Table 1 rows.

    fig: the paper's figure id ("4", "table"); title: one line; paper: what
    the paper shows (its numbers); the script fills scaf (what was measured,
    Markdown), numbers, claims, rows and differs (where the outcome differs
    from the paper's, and why), then calls finish()."""

    def __init__(self, fig, title, paper, argv=None):
        import argparse
        ap = argparse.ArgumentParser(description=title)
        ap.add_argument("--out", required=True, help="folder of the pictures and the JSON record")
        ap.add_argument("--large", action="store_true", help="also the large meshes")
        ap.add_argument("--small", action="store_true",
                        help="the test's subset: small generated inputs, fewer runs")
        ap.add_argument("--rotations", type=int, default=0, help="Fig. 14: number of rotated starts")
        self.args = ap.parse_args(argv)
        self.out = os.path.abspath(self.args.out)
        os.makedirs(self.out, exist_ok=True)
        self.rec = {"fig": fig, "title": title, "paper": paper, "scaf": "", "pictures": [],
                    "numbers": {}, "claims": [], "rows": [], "differs": None, "skipped": None,
                    "mode": "small" if self.args.small else ("large" if self.args.large else "fast")}
        self.t0 = time.monotonic()

    # --- inputs -----------------------------------------------------------------
    def data(self, rel):
        """The absolute path of a shared mesh; Skip when absent (a failure
        under SCAF_REQUIRE_DATA)."""
        p = os.path.join(data_dir(), rel)
        if os.path.exists(p):
            return p
        if data_required():
            print("FAIL: %s is missing and SCAF_REQUIRE_DATA is set" % p)
            sys.exit(1)
        raise Skip("%s is absent (the shared meshes: SCAF_DATA_DIR or ../shared/data)" % rel)

    def path(self, name):
        return os.path.join(self.out, name)

    def tmp(self, name):
        d = os.path.join(self.out, "work")
        os.makedirs(d, exist_ok=True)
        return os.path.join(d, name)

    # --- running scaf -----------------------------------------------------------
    def scaf(self, *args, ok=(0,), timeout=None):
        """Run `scaf ARGS` (with --threads 1 where the command takes it);
        returns (exit code, stdout, stderr, wall seconds)."""
        args = [str(a) for a in args]
        if args[0] in THREADED and "--threads" not in args:
            args += ["--threads", "1"]
        t = time.monotonic()
        p = subprocess.run([scaf_binary()] + args, capture_output=True, text=True, env=child_env(),
                           timeout=timeout)
        dt = time.monotonic() - t
        if p.returncode not in ok:
            raise RuntimeError("scaf %s: exit %d\n%s%s" % (" ".join(args), p.returncode, p.stdout,
                                                           p.stderr[-2000:]))
        return p.returncode, p.stdout, p.stderr, dt

    def check_uv(self, obj):
        """`scaf check --json` of a UV map (exact): the parsed verdict."""
        code, out, _, _ = self.scaf("check", "--json", obj, ok=(0, 1))
        r = json.loads(out)
        r["exit"] = code
        return r

    def check_3d(self, obj):
        code, out, _, _ = self.scaf("check", "--json", "--3d", obj, ok=(0, 1))
        r = json.loads(out)
        r["exit"] = code
        return r

    def gen(self, name, size, out):
        self.scaf("gen", name, "--size", size, "-o", out)
        return out

    # --- the record -------------------------------------------------------------
    def picture(self, name, caption):
        """A PNG scaf wrote into the output folder (name relative to it)."""
        p = self.path(name)
        if os.path.exists(p):
            self.rec["pictures"].append({"file": name, "caption": caption, "bytes": os.path.getsize(p)})

    def claim(self, what, ok):
        ok = bool(ok)
        self.rec["claims"].append({"what": what, "ok": ok})
        print("%s fig %s: %s" % ("ok  " if ok else "FAIL", self.rec["fig"], what))
        return ok

    def row(self, model, paper_model, stand_in, **numbers):
        """A Table 1 row: scaf's numbers (v, f, vs0, vs1, fs0, fs1, it,
        seconds, it_seconds) on `model`, beside the paper's `paper_model`."""
        r = {"model": model, "paper_model": paper_model, "stand_in": stand_in}
        r.update(numbers)
        self.rec["rows"].append(r)

    def finish(self):
        self.rec["seconds"] = time.monotonic() - self.t0
        with open(self.path("fig%s.json" % self.rec["fig"]), "w") as f:
            json.dump(self.rec, f, indent=1)
        bad = [c for c in self.rec["claims"] if not c["ok"]]
        sys.exit(1 if bad else 0)

    def skip(self, why):
        self.rec["skipped"] = str(why)
        print("skip fig %s: %s" % (self.rec["fig"], why))
        self.finish()


def run(fig, body):
    """Run body(fig) with a clean skip when a mesh is absent."""
    try:
        body(fig)
    except Skip as e:
        fig.skip(e)
    fig.finish()


def report_rows(rep):
    """Table 1 numbers from a `scaf param --report` (or atlas/deform) JSON."""
    its = rep.get("iterations") or []
    r = {}
    if its:
        r["vs0"], r["vs1"] = its[0].get("scaffold_vertices"), its[-1].get("scaffold_vertices")
        r["fs0"], r["fs1"] = its[0].get("scaffold_triangles"), its[-1].get("scaffold_triangles")
    return r


def read_json(path):
    with open(path) as f:
        return json.load(f)


def fmt(x, digits=4):
    if x is None:
        return "-"
    if isinstance(x, float):
        if x == 0 or (1e-3 <= abs(x) < 1e5):
            return "%.*f" % (digits, x)
        return "%.2e" % x
    return str(x)


def mean_std(xs):
    n = len(xs)
    m = sum(xs) / n
    s = math.sqrt(sum((x - m) ** 2 for x in xs) / n) if n > 1 else 0.0
    return m, s


def write_obj(path, V, F, UV, FT):
    """An OBJ with v, vt and f v/vt lines (1-based)."""
    with open(path, "w") as f:
        for v in V:
            f.write("v %.17g %.17g %.17g\n" % tuple(v))
        for t in UV:
            f.write("vt %.17g %.17g\n" % tuple(t))
        for a, b in zip(F, FT):
            f.write("f %d/%d %d/%d %d/%d\n" % (a[0] + 1, b[0] + 1, a[1] + 1, b[1] + 1, a[2] + 1, b[2] + 1))
