#!/usr/bin/env python3
"""bench/paper/run_all: remake the SCAF paper's figures and Table 1, write docs/paper.md.

    python3 bench/paper/run_all.py [--large] [--out docs/paper] [--md docs/paper.md]
    python3 bench/paper/run_all.py --small --only 3,4,8,10,13,14 --out /tmp/p --md /tmp/p/paper.md

Runs every figure script of bench/paper (fig*.py, each in its own process)
with the built build/scaf (SCAF_BINARY) and libscaf.so (SCAF_LIBRARY), one
thread; the pictures they make with scaf go into --out, the page into --md
(default: docs/paper.md beside the default --out; else OUT/paper.md). The
default set takes a few minutes on one core; --large adds the large meshes
(Fig. 6 up to 7.09M faces, about 13 GB, Fig. 11's subdivided strip); --small is the
test's subset on small inputs (bench/paper/test_fast.sh); --rotations N
sets Fig. 14's count (default 20; the paper's 1000).

Exit status: 0 every claim held (skips are fine), 1 a claim failed or a
script broke (the page is still written, with the failure marked), 2 usage.
"""
import argparse
import datetime
import glob
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from common import ROOT, child_env, fmt, scaf_binary  # noqa: E402

# The paper's Table 1: (type, model, #V, #F, V_S initial/final, F_S initial/final, iterations, total s, s per it.)
# "(n)" values are the Newton phase, as in the paper.
PAPER_TABLE = [
    ("Atlas", "Nefertiti (Fig. 1)", 1697, 2823, "983/247", "1945/728", "50", "0.71", "0.01"),
    ("Atlas", "Maneki-Neko (Fig. 8)", 23025, 43648, "2427/725", "7174/3770", "50", "16.81", "0.34"),
    ("2D", "Hand (Fig. 3)", 2239, 4046, "347/280", "1104/970", "7", "0.14", "0.02"),
    ("2D", "Spiral (Fig. 4)", 54, 52, "78/36", "190/106", "50 (50)", "0.04 (0.21)", "0.01"),
    ("2D", "Thai Statue (Fig. 5, left)", 42405, 79970, "3665/1593", "12148/8004", "50", "28.28", "0.56"),
    ("2D", "Filigree (Fig. 5, right)", 56062, 100000, "9160/2627", "30422/17356", "100", "75.99", "0.76"),
    ("2D", "Lucy (Fig. 6)", 501105, 1000000, "1856/3470", "5900/5674", "100", "2524.22", "25.24"),
    ("2D", "Lucy (Fig. 6)", 1001375, 1999999, "2284/4400", "7297/7133", "100", "7251.00", "72.51"),
    ("2D", "Lucy (Fig. 6)", 2002031, 3999999, "3587/6930", "11215/10985", "100", "22500.07", "225.00"),
    ("2D", "Lucy (Fig. 6)", 3002899, 5999999, "5135/9859", "16047/15601", "100", "52235.31", "522.35"),
    ("2D", "Lucy (Fig. 6)", 4002816, 8000000, "5140/10288", "15890/15918", "100", "59413.14", "594.13"),
    ("2D", "Lucy (Fig. 6)", 5003408, 10000000, "6194/12231", "19182/19040", "100", "95247.59", "952.47"),
    ("2D", "Lucy (Fig. 6)", 6004111, 12000000, "7357/6418", "2291/21036", "50", "78726.05", "1574.52"),
    ("2D", "Animal (Fig. 7)", 19937, 39040, "747/593", "2306/1998", "50", "15.36", "0.31"),
    ("2D", "Space Filling (Fig. 11)", 79545, 146832, "90815/88237", "181608/176452", "200 (250)",
     "547.13 (1836.58)", "5.30"),
    ("2D", "Horse (Fig. 12)", 20636, 39698, "1343/984", "4238/3520", "30 (10)", "8.26 (12.03)", "0.28 (1.20)"),
    ("2D", "Camel (Fig. 12)", 2032, 3576, "384/272", "1234/1010", "30 (10)", "0.52 (1.13)", "0.02 (0.11)"),
    ("2D", "Cow (Fig. 12)", 3195, 5804, "491/277", "1546/1118", "30 (10)", "0.81 (1.74)", "0.03 (0.17)"),
    ("2D", "Tricera (Fig. 12)", 3163, 5660, "544/329", "1732/1302", "30 (10)", "0.83 (1.77)", "0.03 (0.18)"),
    ("3D", "Leg (Fig. 9)", 6617, 13230, "5016/5021", "68521/68544", "500", "3251.17", "6.50"),
    ("3D", "Bunny (Fig. 10)", 568, 1132, "683/706", "6209/6289", "50", "7.16", "0.14"),
]
ORDER = ["1", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13", "14"]


def scripts():
    found = {}
    for p in sorted(glob.glob(os.path.join(HERE, "fig*.py"))):
        num = os.path.basename(p)[3:5].lstrip("0")
        found[num] = p
    return found


def run_figure(num, path, args, out):
    cmd = [sys.executable, path, "--out", out]
    if args.large:
        cmd.append("--large")
    if args.small:
        cmd.append("--small")
    if args.rotations and num == "14":
        cmd += ["--rotations", str(args.rotations)]
    print("== Fig. %s: %s" % (num, os.path.basename(path)), flush=True)
    env = child_env()
    # the Python side may need the sanitizer preload of test_fast.sh: keep the caller's
    for k in ("LD_PRELOAD", "ASAN_OPTIONS"):
        if k in os.environ:
            env[k] = os.environ[k]
        else:
            env.pop(k, None)
    p = subprocess.run(cmd, env=env, text=True, capture_output=True)
    sys.stdout.write(p.stdout)
    rec_path = os.path.join(out, "fig%s.json" % num)
    rec = None
    if os.path.exists(rec_path):
        with open(rec_path) as f:
            rec = json.load(f)
    if p.returncode != 0 and (rec is None or all(c["ok"] for c in rec.get("claims", []))):
        # a crash, not a failed claim: keep its message for the page
        sys.stdout.write(p.stderr[-3000:])
        rec = rec or {"fig": num, "title": "Fig. %s" % num, "paper": "", "scaf": "", "pictures": [], "claims": [],
                      "rows": [], "differs": None, "skipped": None}
        rec["error"] = (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1]
    return rec


def rel(path, start):
    return os.path.relpath(path, start).replace(os.sep, "/")


def scaf_version():
    try:
        return subprocess.run([scaf_binary(), "--version"], capture_output=True, text=True).stdout.strip()
    except OSError:
        return "?"


def git_commit():
    try:
        return subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True).stdout.strip()
    except OSError:
        return "?"


def table1(recs):
    """Table 1 side by side: each paper row, then scaf's rows for the same model."""
    rows_by_model = {}
    for r in recs:
        for row in r.get("rows", []):
            rows_by_model.setdefault(row["paper_model"], []).append(row)
    out = ["| type | model | who | #V | #F | #V_S initial/final | #F_S initial/final | it. | total s | s / it. |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    seen = set()
    for t in PAPER_TABLE:
        typ, model = t[0], t[1]
        out.append("| %s | %s | paper | %d | %d | %s | %s | %s | %s | %s |" % ((typ, model) + t[2:]))
        if model in seen:
            continue
        if not any(p[1] == model for p in PAPER_TABLE[PAPER_TABLE.index(t) + 1:]):
            seen.add(model)
            for s in rows_by_model.get(model, []):
                vs = "%s/%s" % (fmt(s.get("vs0")), fmt(s.get("vs1"))) if s.get("vs0") is not None else "-"
                fs = "%s/%s" % (fmt(s.get("fs0")), fmt(s.get("fs1"))) if s.get("fs0") is not None else "-"
                who = "**scaf**: %s%s" % (s["model"], " (stand-in)" if s["stand_in"] else "")
                out.append("| | | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                    who, fmt(s.get("v")), fmt(s.get("f")), vs, fs, fmt(s.get("it")),
                    fmt(s.get("seconds"), 2), fmt(s.get("it_seconds"), 3)))
            if not rows_by_model.get(model):
                out.append("| | | **scaf**: not run (see the figure) | | | | | | | |")
    return "\n".join(out)


def page(recs, args, md_dir, out_dir, failed):
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    mode = "--large" if args.large else ("--small (the test's subset)" if args.small else "the default (fast) set")
    L = ["# The SCAF paper, figure by figure, remade by scaf", "",
         "Jiang, Schaefer and Panozzo, *Simplicial Complex Augmentation Framework for Bijective Maps* "
         "(SIGGRAPH Asia 2017): every figure with a result, and Table 1, remade with this repository's "
         "`scaf` on public meshes (the shared test meshes, shared/data beside the checkout or SCAF_DATA_DIR, or meshes scaf generates). "
         "Every picture below was written by scaf itself (`--png`, `--png-seams`, `--checker`).", "",
         "Regenerate it (a few minutes on one core; `--large` adds the large meshes; a missing mesh is "
         "skipped with a line saying so):", "",
         "```sh skip=runs every figure for minutes (the ctest bench/paper_fast runs the fast subset)",
         "python3 bench/paper/run_all.py            # writes docs/paper.md and docs/paper/*.png",
         "```", "",
         "**Timings are this machine's: one run, one thread** (`--threads 1`, `OPENBLAS_NUM_THREADS=1`), on a "
         "shared machine; the paper's are a 2017 desktop's, single-threaded too. Compare outcomes, not "
         "seconds. Energies E are the symmetric Dirichlet energy averaged over the 3D area (4 at an "
         "isometry). Each claim below was checked when the page was made (exact `scaf check` for "
         "bijectivity and self-intersections); `bench/paper_fast` rechecks the fast ones in ctest.", "",
         "Made %s with %s (commit %s), %s." % (now, scaf_version(), git_commit(), mode), ""]
    if failed:
        L += ["**Some claims failed or scripts broke when this page was made: %s.**" % ", ".join(failed), ""]
    L += ["## Summary: the paper's number against scaf's", "", "| figure | the paper | scaf |", "|---|---|---|"]
    for r in recs:
        h = r.get("headline") or {}
        if r.get("skipped"):
            L.append("| [%s](#%s) | %s | skipped: %s |" % (r["fig"], anchor(r), h.get("paper", ""), r["skipped"]))
        elif r.get("error"):
            L.append("| [%s](#%s) | %s | **error**: %s |" % (r["fig"], anchor(r), h.get("paper", ""), r["error"]))
        else:
            L.append("| [%s](#%s) | %s | %s |" % (r["fig"], anchor(r), h.get("paper", ""), h.get("scaf", "")))
    L += ["", "Table 1 side by side is [at the end](#table-1-side-by-side).", ""]
    for r in recs:
        L += ["## %s" % r["title"], ""]
        L += ["**The paper.** %s" % r["paper"], ""]
        if r.get("skipped"):
            L += ["**scaf.** Skipped: %s." % r["skipped"], ""]
            continue
        if r.get("error"):
            L += ["**scaf.** The script failed: `%s`." % r["error"], ""]
            continue
        pics = r.get("pictures", [])
        if pics:
            L.append(" ".join("![%s](%s)" % (p["caption"], rel(os.path.join(out_dir, p["file"]), md_dir))
                              for p in pics))
            L.append("")
            L.append("*" + " · ".join("%s" % p["caption"] for p in pics) + "*")
            L.append("")
        L += ["**scaf.** %s" % r["scaf"], ""]
        claims = r.get("claims", [])
        if claims:
            L.append("Checked:")
            L.append("")
            for c in claims:
                L.append("- %s %s" % ("✓" if c["ok"] else "✗ **failed:**", c["what"]))
            L.append("")
        if r.get("differs"):
            L += ["**Where scaf differs from the paper.** %s" % r["differs"], ""]
    L += ["## Table 1 side by side", "",
          "The paper's rows (its 2017 timings) and, below each model, scaf's on the same model where it is "
          "public (camel, bunny, leg; the hand, spiral and Hilbert strip are the same kind of input) and "
          "on the closest public stand-in where it is not (marked). #V_S / #F_S: scaffold-only vertices / "
          "scaffold triangles (tets in 3D) at the first and last iteration (\"-\" where the command's report "
          "does not give them). The paper's numbers in parentheses are its Newton phase; scaf switches "
          "from SLIM to Newton on its own and counts both in one number. scaf's iterations are run to its "
          "convergence test (the paper ran fixed counts). scaf's seconds: this machine, one thread, one run "
          "(the atlas rows: the whole command; spiral, leg and bunny: wall time of the command).", "",
          table1(recs), ""]
    return "\n".join(L)


def anchor(r):
    t = r["title"].lower()
    keep = "".join(ch for ch in t if ch.isalnum() or ch in " -")
    return keep.replace(" ", "-")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--large", action="store_true")
    ap.add_argument("--small", action="store_true")
    ap.add_argument("--out", default=None, help="folder of the pictures (default docs/paper)")
    ap.add_argument("--md", default=None, help="the page (default docs/paper.md, or OUT/paper.md with --out)")
    ap.add_argument("--only", default=None, help="comma-separated figure numbers, e.g. 3,4,13,14")
    ap.add_argument("--rotations", type=int, default=0)
    ap.add_argument("--keep-work", action="store_true", help="keep the intermediate meshes and records")
    args = ap.parse_args()
    out = os.path.abspath(args.out or os.path.join(ROOT, "docs", "paper"))
    md = os.path.abspath(args.md or (os.path.join(ROOT, "docs", "paper.md") if args.out is None
                                     else os.path.join(out, "paper.md")))
    if not os.access(scaf_binary(), os.X_OK):
        print("run_all: %s is missing: build first (cmake --build build)" % scaf_binary())
        return 2
    os.makedirs(out, exist_ok=True)
    for old in glob.glob(os.path.join(out, "fig*")):  # the pictures of an earlier run
        os.remove(old)
    found = scripts()
    want = ORDER if not args.only else [x.strip() for x in args.only.split(",")]
    recs, failed = [], []
    for num in want:
        if num not in found:
            print("run_all: no script for Fig. %s" % num)
            return 2
        rec = run_figure(num, found[num], args, out)
        recs.append(rec)
        if rec.get("error") or any(not c["ok"] for c in rec.get("claims", [])):
            failed.append("Fig. %s" % num)
    with open(md, "w") as f:
        f.write(page(recs, args, os.path.dirname(md), out, failed))
    if not args.keep_work:
        shutil.rmtree(os.path.join(out, "work"), ignore_errors=True)
        for p in glob.glob(os.path.join(out, "fig*.json")):
            os.remove(p)
    big = [(os.path.basename(p), os.path.getsize(p)) for p in glob.glob(os.path.join(out, "*.png"))
           if os.path.getsize(p) > 80000]
    for name, size in big:
        print("run_all: note: %s is %d bytes" % (name, size))
    n_claims = sum(len(r.get("claims", [])) for r in recs)
    print("run_all: %d figures, %d claims, %s; page %s" % (len(recs), n_claims,
                                                             "all held" if not failed else "FAILED: " + ", ".join(failed),
                                                             md))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
