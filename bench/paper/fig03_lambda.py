#!/usr/bin/env python3
"""Fig. 3: the scaffold weight lambda changes the iterations, not the result.

scaf param with --lambda-ratio 1, 0.01 (the paper's 1/100, the default) and
0.0001 (x100, x1, x0.01 of the paper's weight) on disk/hand_lowres.obj (a
public hand standing in for the paper's; --small: a generated hemisphere).
Claims: every map bijective (scaf check), the three final energies equal
within the convergence tolerance (1e-5 relatively)."""
from common import Figure, fmt, read_json, report_rows, run

PAPER = ("Three weights lambda (100x the paper's, the paper's 1/100 E_M/|S|, and 0.01x) give "
         "indistinguishable maps of a hand; they took 9, 7 and 8 iterations to reach the same energy "
         "(Table 1: Hand, 2,239 vertices, 4,046 faces, 7 iterations, 0.14 s).")
RATIOS = [("100x", 1.0), ("1x (default)", 0.01), ("0.01x", 0.0001)]


def body(fig):
    if fig.args.small:
        mesh = fig.gen("hemisphere", 8, fig.tmp("hemisphere8.obj"))
        name = "generated hemisphere (384 faces)"
    else:
        mesh = fig.data("disk/hand_lowres.obj")
        name = "disk/hand_lowres.obj"
    rows, finals = [], []
    for label, r in RATIOS:
        tag = str(r).replace(".", "_")
        out, rep = fig.tmp("fig03_%s.obj" % tag), fig.tmp("fig03_%s.json" % tag)
        png = fig.path("fig03_lambda_%s.png" % tag)
        _, _, _, wall = fig.scaf("param", mesh, "-o", out, "--lambda-ratio", r, "--report", rep,
                                 "--png", png, "--png-size", 220, "--checker", "--quiet")
        d = read_json(rep)
        E = [i["energy"] for i in d["iterations"]]
        f = d["final_energy"]
        to1 = next((k + 1 for k, e in enumerate(E) if e <= f * 1.01), None)
        chk = fig.check_uv(out)
        fig.claim("lambda ratio %g: the map is bijective (scaf check)" % r, chk["bijective"])
        finals.append(f)
        rows.append((label, r, d["iteration_count"], to1, f, d["seconds"]))
        fig.picture("fig03_lambda_%s.png" % tag, "lambda %s: E %.6f after %d iterations" %
                    (label, f, d["iteration_count"]))
        if r == 0.01:
            m = d["mesh"]
            fig.row(name, "Hand (Fig. 3)", not fig.args.small, v=m["vertices"], f=m["faces"],
                    it=d["iteration_count"], seconds=d["seconds"],
                    it_seconds=d["median_seconds_per_iteration"], **report_rows(d))
    spread = (max(finals) - min(finals)) / min(finals)
    fig.claim("the final energies agree within the convergence tolerance 1e-5 (spread %.2e)" % spread, spread < 1e-5)
    fig.rec["numbers"] = {"runs": [dict(zip(("weight", "ratio", "iterations", "to_1pct", "E", "seconds"), x))
                                   for x in rows], "relative_spread": spread}
    lines = ["| lambda | --lambda-ratio | iterations to convergence | iterations to within 1% of E | final E |",
             "|---|---|---|---|---|"]
    for label, r, it, to1, f, _ in rows:
        lines.append("| %s | %g | %d | %s | %.8f |" % (label, r, it, fmt(to1), f))
    fig.rec["scaf"] = ("On %s, run to convergence (--tolerance 1e-5):\n\n%s\n\nThe final energies differ by "
                       "%.1e relatively: lambda changes how fast, not where the map ends." %
                       (name, "\n".join(lines), spread))
    fig.rec["headline"] = {
        "paper": "9 / 7 / 8 iterations, same energy",
        "scaf": "%s iterations (to within 1%%: %s), final E spread %.1e" % (
            " / ".join(str(x[2]) for x in rows), " / ".join(fmt(x[3]) for x in rows), spread)}
    fig.rec["differs"] = None if fig.args.small else (
        "The counts are larger than the paper's 7-9 because scaf runs to its convergence test "
        "(relative distance to the minimum below 1e-5, Newton at the end) from a mean-value start "
        "whose E is about 3e7 on this hand; to within 1% of the final E all three need about the "
        "same number of iterations, as in the paper.")


if __name__ == "__main__":
    run(Figure("3", "Fig. 3: lambda changes the iterations, not the result", PAPER), body)
