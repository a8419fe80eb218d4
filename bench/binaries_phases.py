#!/usr/bin/env python3
"""Two (or more) scaf binaries alternated run by run on one mesh: per run,
the median over iterations 2..K of the seconds per iteration and per
phase, and iteration / factorization (issue 15's ratio: a SLIM iteration
against its one numeric factorization).

    bench/binaries_phases.py --rounds 4 --iterations 10 \\
        /work/shared/data/disk/aphrodite.obj OLD/scaf build/scaf

Each run: `SCAF param MESH -o TMP.obj --init harmonic --iterations K
--tolerance 0 --solver slim --threads T --report TMP.json --quiet`. The
binaries take turns (A, B, A, B, ...) so that the host's changes of speed
(on shared machines, tens of seconds long) hit each alike: compare within
a round. Also says whether the output files are byte-identical across the
binaries (the same code path, a changed speed only). Timing only: no test
depends on it.
"""
import argparse
import filecmp
import json
import os
import statistics
import subprocess
import sys
import tempfile

PHASES = ["factorization", "solve", "assembly", "line_search", "analysis", "scaffold", "other"]


def run(scaf, mesh, iterations, threads, out, report):
    subprocess.run([scaf, "param", mesh, "-o", out, "--init", "harmonic", "--iterations",
                    str(iterations), "--tolerance", "0", "--solver", "slim", "--threads",
                    str(threads), "--report", report, "--quiet"], check=True)
    its = json.load(open(report))["iterations"][1:]
    if not its:
        sys.exit("need at least 2 iterations")
    ms = {p: 1000 * statistics.median(i["phase_seconds"][p] for i in its) for p in PHASES}
    ms["iteration"] = 1000 * statistics.median(i["seconds"] for i in its)
    return ms


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mesh")
    ap.add_argument("scaf", nargs="+", help="binaries, alternated in this order")
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--iterations", type=int, default=10)
    ap.add_argument("--threads", type=int, default=1)
    a = ap.parse_args()
    cols = ["iteration"] + PHASES
    print("| round | binary | load | " + " | ".join(cols) + " | iteration / factorization |")
    print("|---" * (len(cols) + 4) + "|")
    with tempfile.TemporaryDirectory() as tmp:
        outs = [os.path.join(tmp, "out%d.obj" % k) for k in range(len(a.scaf))]
        same = True
        for r in range(a.rounds):
            for k, scaf in enumerate(a.scaf):
                load = os.getloadavg()[0]
                ms = run(scaf, a.mesh, a.iterations, a.threads, outs[k],
                         os.path.join(tmp, "r%d.json" % k))
                print("| %d | %s | %.2f | " % (r + 1, chr(ord("A") + k), load) +
                      " | ".join("%.2f" % ms[c] for c in cols) +
                      " | %.3f |" % (ms["iteration"] / ms["factorization"]), flush=True)
            same = same and all(filecmp.cmp(outs[0], o, shallow=False) for o in outs[1:])
        print()
        for k, scaf in enumerate(a.scaf):
            print("%s: %s" % (chr(ord("A") + k), scaf))
        print("outputs byte-identical across binaries: %s" % ("yes" if same else "no"))


if __name__ == "__main__":
    main()
