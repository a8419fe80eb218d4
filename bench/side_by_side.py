#!/usr/bin/env python3
"""Side-by-side benchmark: scaf against libigl's SCAF (the reference harness).

Runs `scaf param` and the reference harness of ../shared/reference
(scaf_reference, built by its build.sh; never part of this project) on the
same meshes from the same start -- libigl's tutorial start, boundary on a
circle of the mesh's area and harmonic (cotangent) interior, which is what
`scaf param --init harmonic` computes -- interleaved: every round runs both
programs back to back, alternating which goes first, so that the load of the
shared machine hits both alike. Single-threaded (OPENBLAS_NUM_THREADS=1,
OMP_NUM_THREADS=1; the harness sets libigl's own thread count to 1).

Seconds per iteration are measured the same way for both: each program's own
timer around one iteration (the harness times each scaf_solve(1) call, scaf
reports each iteration's seconds in `--report` JSON, including its scaffold
rebuild, as libigl's call does). The headline figure of a run is the median
over iterations 2..N (iteration 1 of scaf carries the one-time METIS
ordering); the mean over 1..N is printed too. Over the rounds the median of
the runs is taken. Energies E = sum_f A_f (|J|^2 + |J^-1|^2) / sum_f A_f over
the mesh triangles are compared at equal iteration counts (both programs
compute this quantity independently); the start energies E0 must agree.

Prints Markdown (paste into bench/RESULTS-param.md): the load (/proc/loadavg)
before and after every mesh, the CPU share of each run (process CPU time /
wall time: below ~0.95 the run waited for a core), the ratio per round and
over the rounds where both runs had a core, the summary table, and scaf's
phase split (mean of iterations 2..N of its median run).

    bench/side_by_side.py [--reference BIN] [--scaf BIN] [--data DIR]
                          [--rounds N] [--cpu] [--to-energy] [--scaf-args ARGS]
                          [MESH[:ITERATIONS] ...]

--to-energy measures time to energy instead: libigl runs ITERATIONS
iterations from its tutorial start and its final E is the target; scaf runs
with its own defaults (mean-value start, auto solver) but --tolerance 0 and
--iterations --scaf-iterations (default 60), and the time each needs to
reach E <= target is compared: libigl the sum of its iteration seconds up
to the first iteration at or below the target, scaf its setup (embedding)
plus its iteration seconds up to that point (scaf's setup is counted,
libigl's is not: the comparison leans towards libigl). Also interleaved,
alternating which program goes first.

--scaf-args: more `scaf param` options for the per-iteration mode, default
`--solver slim` (libigl's SCAF iterates SLIM; scaf's default solver, auto,
turns to Newton steps after a few iterations, a different method per
iteration). MESH may be absolute
(e.g. an upsampled mesh from bench/subdivide.py).

--cpu adds CPU seconds per iteration (2..N): each program is run once more
per round, stopped after iteration 1, and the difference of the two
processes' CPU times is divided by N - 1; unlike the wall time it does not
count the time a run waited for a core on a loaded machine.

BIN defaults to $SCAF_REFERENCE; without a reference binary the script says
so and exits 0 (skipped). --scaf defaults to build/scaf next to this folder,
--data to $SCAF_DATA_DIR or ../shared/data beside the repository. Default
meshes: disk/camel_b.obj:50 disk/camelhead.off:50 disk/aphrodite.obj:10.
Exit status: 0 ok or skipped, 1 a run failed, 2 usage.
"""
import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
DEFAULT_MESHES = ["disk/camel_b.obj:50", "disk/camelhead.off:50", "disk/aphrodite.obj:10"]
PHASES = ["factorization", "analysis", "solve", "assembly", "line_search", "scaffold", "other"]
# A run whose process had a core for at least this share of its wall time
# was not kept waiting by the other jobs of the machine.
CLEAN_CPU_SHARE = 0.95
# Energies printed by the harness have 6 decimals; relative agreement of the
# start energies beyond that means the start differs.
START_RTOL = 1e-6


class RunFailed(Exception):
    pass


def loadavg():
    try:
        with open("/proc/loadavg") as f:
            return " ".join(f.read().split()[:3])
    except OSError:
        return "n/a"


def run_timed(cmd, env):
    """Runs cmd; returns (stdout, wall seconds) of the child."""
    t0 = time.monotonic()
    p = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    out, errtext = p.communicate()
    wall = time.monotonic() - t0
    # communicate() has reaped the child: the caller takes its CPU time as
    # the RUSAGE_CHILDREN difference around this call.
    if p.returncode != 0:
        raise RunFailed("%s exited with %d: %s" % (" ".join(cmd), p.returncode, errtext.strip()[-400:]))
    return out, wall


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def parse_reference(text):
    """Returns {"E0", "secs": [s_1..s_N], "E": [E_1..E_N], "flipped": max, "area"}."""
    secs, energies, e0, flipped, area = [], [], None, 0, None
    for line in text.splitlines():
        w = line.split()
        if line.startswith("# mesh") and "area" in w:
            area = float(w[w.index("area") + 1])
        if len(w) >= 8 and w[0] == "it" and w[2] == "sec" and w[4] == "E" and w[6] == "flipped":
            k, s, e, fl = int(w[1]), float(w[3]), float(w[5]), int(w[7])
            flipped = max(flipped, fl)
            if k == 0:
                e0 = e
            else:
                if k != len(secs) + 1:
                    raise RunFailed("reference output: iteration %d out of order" % k)
                secs.append(s)
                energies.append(e)
    if e0 is None or not secs:
        raise RunFailed("reference output has no iterations:\n" + text[-400:])
    return {"E0": e0, "secs": secs, "E": energies, "flipped": flipped, "area": area}


def parse_scaf_report(path):
    with open(path) as f:
        r = json.load(f)
    its = r["iterations"]
    return {
        "E0": r["initial_energy"],
        "secs": [it["seconds"] for it in its],
        "E": [it["energy"] for it in its],
        "phases": [it["phase_seconds"] for it in its],
        "faces": r["mesh"]["faces"],
    }


def per_iteration(secs):
    """(median of iterations 2..N, mean of 1..N) of one run."""
    tail = secs[1:] if len(secs) > 1 else secs
    return statistics.median(tail), sum(secs) / len(secs)


def fmt_s(x):
    return "%.4g" % x


def time_to(target, secs, energies, setup=0.0):
    """(seconds, iterations) until the first E <= target, or (None, None).
    E is compared as the harness prints it (6 decimals): aphrodite's
    libigl target 6.372086 is below scaf's minimum 6.3720864 by less than
    that precision."""
    t = setup
    for k, (s_k, e_k) in enumerate(zip(secs, energies)):
        t += s_k
        if round(e_k, 6) <= target:
            return t, k + 1
    return None, None


def bench_to_energy(args, rel, iterations, env, tmp):
    """Time to libigl's ITERATIONS-iteration energy, both programs (see --to-energy)."""
    path = os.path.join(args.data, rel)
    if not os.path.exists(path):
        print("### %s: missing (%s), skipped\n" % (rel, path))
        return None
    report = os.path.join(tmp, "report.json")
    ref_cmd = [args.reference, path, str(iterations), "-"] + ([repr(args.scale)] if args.scale != 1.0 else [])
    scaf_cmd = [args.scaf, "param", path, "-o", os.path.join(tmp, "out.obj"), "--tolerance", "0",
                "--iterations", str(args.scaf_iterations), "--quiet", "--report", report]
    rows = []
    load_before = loadavg()
    for rnd in range(args.rounds):
        order = ["libigl", "scaf"] if rnd % 2 == 0 else ["scaf", "libigl"]
        got = {}
        for who in order:
            if who == "libigl":
                out, wall = run_timed(ref_cmd, env)
                got[who] = parse_reference(out)
                got[who]["wall"] = wall
            else:
                _, wall = run_timed(scaf_cmd, env)
                with open(report) as f:
                    r = json.load(f)
                got[who] = {"secs": [it["seconds"] for it in r["iterations"]],
                            "E": [it["energy"] for it in r["iterations"]], "setup": r["setup_seconds"],
                            "wall": wall}
        target = got["libigl"]["E"][-1]
        tl, kl = time_to(target, got["libigl"]["secs"], got["libigl"]["E"])
        ts, ks = time_to(target, got["scaf"]["secs"], got["scaf"]["E"], got["scaf"]["setup"])
        rows.append({"target": target, "libigl": (tl, kl), "scaf": (ts, ks),
                     "scaf_best": min(got["scaf"]["E"])})
        print("side_by_side: %s round %d: target %.6f; libigl %s s (%s its), scaf %s s (%s its)"
              % (rel, rnd + 1, target, tl, kl, ts, ks), file=sys.stderr)
    load_after = loadavg()
    print("### %s: time to libigl's %d-iteration energy (%d rounds)\n" % (rel, iterations, args.rounds))
    print("load before %s, after %s\n" % (load_before, load_after))
    print("| round | target E (libigl after %d) | libigl s (its) | scaf s incl. setup (its) | ratio |" % iterations)
    print("|---|---|---|---|---|")
    ratios = []
    for i, r in enumerate(rows):
        (tl, kl), (ts, ks) = r["libigl"], r["scaf"]
        q = tl / ts if tl and ts else None
        if q:
            ratios.append(q)
        print("| %d | %.6f | %s (%s) | %s (%s) | %s |"
              % (i + 1, r["target"], fmt_s(tl) if tl else "-", kl, fmt_s(ts) if ts else "not reached", ks,
                 "%.1f" % q if q else "-"))
    if ratios:
        print("\nmedian ratio libigl / scaf: **%.1f** (range %.1f-%.1f)\n"
              % (statistics.median(ratios), min(ratios), max(ratios)))
    return ratios


def bench_mesh(args, rel, iterations, env, tmp):
    path = os.path.join(args.data, rel)
    if not os.path.exists(path):
        print("### %s: missing (%s), skipped\n" % (rel, path))
        return None
    report = os.path.join(tmp, "report.json")

    def ref_cmd(n):
        return [args.reference, path, str(n), "-"] + ([repr(args.scale)] if args.scale != 1.0 else [])

    def scaf_cmd(n):
        return [args.scaf, "param", path, "-o", os.path.join(tmp, "out.obj"), "--init", "harmonic",
                "--iterations", str(n), "--tolerance", "0", "--quiet", "--report", report] + args.scaf_args.split()
    runs = {"libigl": [], "scaf": []}
    load_before = loadavg()
    loads = []
    for rnd in range(args.rounds):
        order = ["libigl", "scaf"] if rnd % 2 == 0 else ["scaf", "libigl"]
        for who in order:
            la = loadavg()
            loads.append(float(la.split()[0]) if la != "n/a" else 0.0)
            c0 = child_cpu()
            if who == "libigl":
                out, wall = run_timed(ref_cmd(iterations), env)
                res = parse_reference(out)
            else:
                _, wall = run_timed(scaf_cmd(iterations), env)
                res = parse_scaf_report(report)
            cpu = child_cpu() - c0
            res["cpu_share"] = cpu / wall if wall > 0 else 0.0
            if len(res["secs"]) != iterations:
                raise RunFailed("%s ran %d of %d iterations on %s" % (who, len(res["secs"]), iterations, rel))
            if args.cpu:
                # the same run stopped after iteration 1: the difference of
                # the process CPU times is iterations 2..N, waiting excluded
                c1 = child_cpu()
                run_timed((ref_cmd if who == "libigl" else scaf_cmd)(1), env)
                res["cpu_it"] = (cpu - (child_cpu() - c1)) / (iterations - 1)
            res["cpu_share"] = min(res["cpu_share"], 1.0)  # rusage ticks can round above the wall time
            runs[who].append(res)
            print("side_by_side: %s round %d %s: median(2..N) %.5f s/it, E_N %.6f, CPU share %.2f"
                  % (rel, rnd + 1, who, per_iteration(res["secs"])[0], res["E"][-1], res["cpu_share"]),
                  file=sys.stderr)
    load_after = loadavg()
    return summarize(rel, iterations, runs, load_before, load_after, loads)


def summarize(rel, iterations, runs, load_before, load_after, loads):
    s = {"rel": rel, "N": iterations, "rounds": len(runs["scaf"]), "faces": runs["scaf"][0]["faces"],
         "load": (load_before, load_after, min(loads), max(loads))}
    for who in ("libigl", "scaf"):
        med = [per_iteration(r["secs"])[0] for r in runs[who]]
        mean = [per_iteration(r["secs"])[1] for r in runs[who]]
        s[who] = {
            "med": statistics.median(med), "med_runs": med,
            "mean": statistics.median(mean),
            "E0": runs[who][0]["E0"], "EN": runs[who][0]["E"][-1],
            "E": runs[who][0]["E"],
            # the same program on the same input must land on the same E
            "deterministic": all(r["E"] == runs[who][0]["E"] for r in runs[who]),
            "cpu_share": (min(r["cpu_share"] for r in runs[who]), max(r["cpu_share"] for r in runs[who])),
        }
    # rounds pair the two programs in the same minute: the median of the
    # per-round ratios is the figure least moved by a load change between rounds
    s["round_ratios"] = [a / b for a, b in zip(s["libigl"]["med_runs"], s["scaf"]["med_runs"])]
    s["ratio"] = statistics.median(s["round_ratios"])
    # rounds in which both runs had a core nearly all their wall time
    s["clean_ratios"] = [q for q, a, b in zip(s["round_ratios"], runs["libigl"], runs["scaf"])
                         if min(a["cpu_share"], b["cpu_share"]) >= CLEAN_CPU_SHARE]
    if all("cpu_it" in r for who in runs for r in runs[who]):
        s["cpu"] = {who: statistics.median(r["cpu_it"] for r in runs[who]) for who in runs}
        s["cpu_ratio"] = statistics.median(a["cpu_it"] / b["cpu_it"] for a, b in zip(runs["libigl"], runs["scaf"]))
    s["flipped"] = max(r["flipped"] for r in runs["libigl"])
    s["same_start"] = abs(s["scaf"]["E0"] - s["libigl"]["E0"]) <= START_RTOL * abs(s["libigl"]["E0"]) + 5e-7
    # scaf's phase split of the run whose median(2..N) is the median run
    runs_sorted = sorted(runs["scaf"], key=lambda r: per_iteration(r["secs"])[0])
    mid = runs_sorted[(len(runs_sorted) - 1) // 2]
    tail = range(1, len(mid["secs"])) if len(mid["secs"]) > 1 else range(len(mid["secs"]))
    # means, not medians: the phases of a mean iteration add up to it
    s["phases"] = {k: statistics.mean(mid["phases"][i].get(k, 0.0) for i in tail) for k in PHASES}
    s["phase_it"] = statistics.mean(mid["secs"][i] for i in tail)
    s["phase_unaccounted"] = statistics.mean(mid["secs"][i] - sum(mid["phases"][i].values()) for i in tail)
    s["first_it"] = {"secs": mid["secs"][0], "analysis": mid["phases"][0].get("analysis", 0.0)}
    return s


def print_mesh(s):
    rel, n = s["rel"], s["N"]
    L, S = s["libigl"], s["scaf"]
    print("### %s (%d faces, %d iterations, %d rounds)\n" % (rel, s["faces"], n, s["rounds"]))
    print("load before %s, after %s (1-min load at each run %.2f-%.2f)\n" % s["load"])
    print("| | libigl | scaf | libigl / scaf |")
    print("|---|---|---|---|")
    print("| median s/it, its 2..%d (median of rounds) | %s | %s | %.2f |"
          % (n, fmt_s(L["med"]), fmt_s(S["med"]), L["med"] / S["med"]))
    print("| mean s/it, its 1..%d (median of rounds) | %s | %s | %.2f |"
          % (n, fmt_s(L["mean"]), fmt_s(S["mean"]), L["mean"] / S["mean"]))
    if "cpu" in s:
        print("| CPU s/it, its 2..%d: CPU of the run minus CPU of a 1-iteration run (median; ratio: median per round) "
              "| %s | %s | %.2f |" % (n, fmt_s(s["cpu"]["libigl"]), fmt_s(s["cpu"]["scaf"]), s["cpu_ratio"]))
    print("| per-round median s/it | %s | %s | |"
          % (" ".join(fmt_s(x) for x in L["med_runs"]), " ".join(fmt_s(x) for x in S["med_runs"])))
    print("| per-round ratio libigl / scaf (median %.2f) | | | %s |"
          % (s["ratio"], " ".join("%.2f" % x for x in s["round_ratios"])))
    print("| ratio in the rounds where both runs had CPU share >= %.2f | | | %s |"
          % (CLEAN_CPU_SHARE, clean_text(s)))
    print("| CPU share of the runs | %.2f-%.2f | %.2f-%.2f | |" % (L["cpu_share"] + S["cpu_share"]))
    print("| E0 (start) | %.6f | %.6f | %s |" % (L["E0"], S["E0"], "same start" if s["same_start"] else "DIFFERENT START"))
    for k in sorted({1, max(1, n // 2), n}):
        print("| E after %d | %.6f | %.6f | %+.2g |" % (k, L["E"][k - 1], S["E"][k - 1], S["E"][k - 1] - L["E"][k - 1]))
    notes = []
    if s["flipped"]:
        notes.append("libigl had %d flipped triangles" % s["flipped"])
    for who in ("libigl", "scaf"):
        if not s[who]["deterministic"]:
            notes.append("%s's energies differ between rounds" % who)
    if notes:
        print("\nNote: " + "; ".join(notes) + ".")
    ph, it = s["phases"], s["phase_it"]
    split = ", ".join("%s %.4f (%.0f%%)" % (k, ph[k], 100 * ph[k] / it) for k in PHASES)
    print("\nscaf, mean over iterations 2..%d of the run with the median s/it: iteration %.4f s = %s, untimed %.4f (%.0f%%); "
          "iteration / factorization %.2f. Iteration 1: %.4f s, analysis (with the ordering) %.4f s.\n"
          % (n, it, split, s["phase_unaccounted"], 100 * s["phase_unaccounted"] / it,
             it / ph["factorization"] if ph["factorization"] > 0 else 0.0, s["first_it"]["secs"],
             s["first_it"]["analysis"]))


def clean_text(s):
    c = s["clean_ratios"]
    return "%.2f (%d of %d)" % (statistics.median(c), len(c), s["rounds"]) if c else "none of %d" % s["rounds"]


def print_summary(results):
    print("### Summary\n")
    print("| mesh | faces | its | libigl s/it | scaf s/it | ratio | ratio per round: median (range) | clean rounds: median ratio | CPU s/it libigl / scaf (ratio) | E libigl | E scaf | load before / after |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for s in results:
        cpu = ("%s / %s (%.2f)" % (fmt_s(s["cpu"]["libigl"]), fmt_s(s["cpu"]["scaf"]), s["cpu_ratio"])
               if "cpu" in s else "-")
        print("| %s | %d | %d | %s | %s | %.2f | %.2f (%.2f-%.2f) | %s | %s | %.5f | %.5f | %s / %s |"
              % (s["rel"], s["faces"], s["N"], fmt_s(s["libigl"]["med"]), fmt_s(s["scaf"]["med"]),
                 s["libigl"]["med"] / s["scaf"]["med"], s["ratio"], min(s["round_ratios"]),
                 max(s["round_ratios"]), clean_text(s), cpu, s["libigl"]["EN"], s["scaf"]["EN"],
                 s["load"][0].split()[0], s["load"][1].split()[0]))
    print("\ns/it: median over iterations 2..N of each run, median over the rounds; ratio = libigl / scaf "
          "of those; ratio per round: the two runs of one round divided, median and range over the rounds; "
          "clean rounds: those where both runs had a core >= %.0f%% of their wall time (their count); "
          "CPU s/it (--cpu): process CPU seconds of the N-iteration run minus those of a 1-iteration run, "
          "over N - 1 (waiting for a core excluded; contention for caches and memory is not); "
          "E after N iterations; load: 1-minute load average." % (100 * CLEAN_CPU_SHARE))


def git_head():
    try:
        out = subprocess.run(["git", "-C", REPO, "describe", "--always", "--dirty"], capture_output=True,
                             text=True, check=True).stdout.strip()
        return out or "unknown"
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def parse_mesh_arg(a):
    rel, _, its = a.rpartition(":")
    if not rel or not its.isdigit() or int(its) < 2:
        raise argparse.ArgumentTypeError("%s: expected MESH:ITERATIONS with ITERATIONS >= 2" % a)
    return rel, int(its)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("meshes", nargs="*", type=parse_mesh_arg, metavar="MESH:ITERATIONS",
                    help="mesh path relative to --data (or absolute), iteration count")
    ap.add_argument("--reference", default=os.environ.get("SCAF_REFERENCE", ""),
                    help="scaf_reference binary (default $SCAF_REFERENCE)")
    ap.add_argument("--scaf", default=os.path.join(REPO, "build", "scaf"), help="scaf binary")
    ap.add_argument("--data", default=os.environ.get("SCAF_DATA_DIR") or
                    os.path.join(os.path.dirname(REPO), "shared", "data"), help="mesh folder")
    ap.add_argument("--rounds", type=int, default=5, help="interleaved rounds per mesh (default 5)")
    ap.add_argument("--cpu", action="store_true",
                    help="also measure CPU seconds per iteration (one more 1-iteration run of each program per round)")
    ap.add_argument("--to-energy", action="store_true",
                    help="time to libigl's ITERATIONS-iteration energy instead of seconds per iteration")
    ap.add_argument("--scaf-iterations", type=int, default=60,
                    help="--to-energy: scaf's iteration cap (default 60)")
    ap.add_argument("--scaf-args", default="--solver slim",
                    help="more scaf param options (default '--solver slim': libigl iterates SLIM, and scaf's "
                         "default solver, auto, turns to Newton steps after a few iterations)")
    ap.add_argument("--scale", type=float, default=1.0,
                    help="reference only: scale the mesh (libigl's SCAF is not scale-invariant; E is)")
    args = ap.parse_args()
    if args.rounds < 1:
        ap.error("--rounds must be at least 1")
    if not args.reference or not os.access(args.reference, os.X_OK):
        print("side_by_side: skipped: no reference binary (%s); build it with ../shared/reference/build.sh "
              "and pass --reference or set SCAF_REFERENCE" % (args.reference or "SCAF_REFERENCE unset"))
        return 0
    if not os.access(args.scaf, os.X_OK):
        print("side_by_side: no scaf binary at %s (build the project first or pass --scaf)" % args.scaf,
              file=sys.stderr)
        return 2
    meshes = args.meshes or [parse_mesh_arg(m) for m in DEFAULT_MESHES]
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    print("## Side by side: scaf vs libigl SCAF, %s\n" % time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()))
    print("`bench/side_by_side.py --rounds %d%s --scaf-args '%s' %s` (scaf %s, %s; reference %s; %d CPUs; "
          "OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1)\n"
          % (args.rounds, " --cpu" if args.cpu else "", args.scaf_args, " ".join("%s:%d" % m for m in meshes),
             git_head(), os.path.relpath(args.scaf, REPO),
             args.reference, os.cpu_count() or 0))
    results = []
    tmp = tempfile.mkdtemp(prefix="side_by_side.")
    try:
        for rel, its in meshes:
            if args.to_energy:
                bench_to_energy(args, rel, its, env, tmp)
                sys.stdout.flush()
                continue
            s = bench_mesh(args, rel, its, env, tmp)
            if s:
                print_mesh(s)
                results.append(s)
                sys.stdout.flush()
    except RunFailed as e:
        print("side_by_side: %s" % e, file=sys.stderr)
        return 1
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if results:
        print_summary(results)
    return 0


if __name__ == "__main__":
    sys.exit(main())
