#!/usr/bin/env python3
"""Seconds per iteration and per phase of `scaf param` at several thread
counts, runs interleaved (1, 2, 1, 2, ...) so that a change of load hits
every count alike.

    bench/threads_phases.py --scaf build/scaf --rounds 2 --threads 1,2 \\
        /work/shared/data/disk/aphrodite.obj

Each run: `nice SCAF param MESH -o TMP.obj --init harmonic --iterations K
--tolerance 0 --solver slim --threads T --report TMP.json --quiet`
(K = --iterations, default 4), wall and CPU seconds of the process
(os.wait4) and the 1-minute load before it. Per run and per count, the
median over iterations 2..K of the report's per-iteration phase seconds
(wall clock). Prints a Markdown table per run, then the medians over the
runs per count and the ratios 1-thread / N-thread per phase. Timing only:
no test depends on it.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

PHASES = ["assembly", "analysis", "factorization", "solve", "line_search", "scaffold", "other"]


def run(scaf, mesh, threads, iterations, tmp):
    out = os.path.join(tmp, "o.obj")
    rep = os.path.join(tmp, "r.json")
    load = os.getloadavg()[0]
    cmd = ["nice", scaf, "param", mesh, "-o", out, "--init", "harmonic", "--iterations",
           str(iterations), "--tolerance", "0", "--solver", "slim", "--threads", str(threads),
           "--report", rep, "--quiet"]
    env = dict(os.environ)
    env.pop("OPENBLAS_NUM_THREADS", None)
    t0 = time.monotonic()
    p = subprocess.Popen(cmd, env=env)
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.monotonic() - t0
    if status != 0:
        sys.exit("run failed: %s" % " ".join(cmd))
    with open(rep) as f:
        r = json.load(f)
    its = r["iterations"][1:]
    ph = {k: statistics.median(i["phase_seconds"][k] for i in its) for k in PHASES}
    ph["iteration"] = statistics.median(i["seconds"] for i in its)
    return {"threads": threads, "load": load, "wall": wall, "cpu": ru.ru_utime + ru.ru_stime,
            "sys": ru.ru_stime, "energy": r["final_energy"], "phases": ph}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("mesh")
    ap.add_argument("--scaf", default="build/scaf")
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--iterations", type=int, default=4)
    a = ap.parse_args()
    counts = [int(t) for t in a.threads.split(",")]
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(a.rounds):
            for t in counts:
                runs.append(run(a.scaf, a.mesh, t, a.iterations, tmp))
    cols = ["iteration"] + PHASES
    print("| T | load | wall s | CPU s (sys) | E | " + " | ".join(cols) + " |")
    print("|---" * (5 + len(cols)) + "|")
    for r in runs:
        print("| %d | %.2f | %.2f | %.2f (%.2f) | %.15g | " % (r["threads"], r["load"], r["wall"],
                                                           r["cpu"], r["sys"], r["energy"]) +
              " | ".join("%.4f" % r["phases"][c] for c in cols) + " |")
    med = {}
    for t in counts:
        rs = [r for r in runs if r["threads"] == t]
        med[t] = {c: statistics.median(r["phases"][c] for r in rs) for c in cols}
    print()
    print("| T | " + " | ".join(cols) + " |")
    print("|---" * (1 + len(cols)) + "|")
    for t in counts:
        print("| %d | " % t + " | ".join("%.4f" % med[t][c] for c in cols) + " |")
    for t in counts[1:]:
        print("| 1/%d | " % t + " | ".join(
            "%.2fx" % (med[counts[0]][c] / med[t][c]) if med[t][c] > 0 else "-" for c in cols) +
              " |")


if __name__ == "__main__":
    main()
