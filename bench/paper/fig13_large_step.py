#!/usr/bin/env python3
"""Fig. 13: one iteration takes a step far larger than a 1-ring.

From the Tutte start of disk/hand_lowres.obj (its fingers are crushed into
tiny triangles: the paper's extreme scale difference; also with --small),
one SCAF iteration through the Python API (scaf.Param: the start, run(1),
the map after): for every vertex, its displacement divided by the mean
length of its 1-ring's edges in the start; the largest ratio is the paper's
"150 times". The pictures are `scaf param --init tutte --iterations 0 / 1
--png`. Claims: the map after one iteration is bijective (scaf check), E
falls by more than half, and the largest displacement is more than 10
1-ring edge lengths (a local method moves a vertex within its 1-ring)."""
import math

from common import Figure, import_scaf, read_json, run

PAPER = ("One iteration from Tutte's embedding drastically reduces the distortion: the highlighted vertex "
         "moves 150 times the average edge length of its 1-ring in one step, where coordinate descent would "
         "need hundreds of iterations; the ratio of the smallest to the largest triangle area in the start "
         "is 1e-6.")


def tri_area(a, b, c):
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


def body(fig):
    mesh = fig.data("disk/hand_lowres.obj")  # small (1,602 faces): --small too
    name = "disk/hand_lowres.obj"
    scaf = import_scaf()
    V, F, _, _ = scaf.read_obj(mesh)
    with scaf.Param(init="tutte", tolerance=0.0) as p:
        p.set_mesh(V, F)
        U0, FT = p.get_uv()
        e0 = p.energy
        p.run(1)
        U1, _ = p.get_uv()
        e1 = p.energy
    ring = [[] for _ in U0]
    for t in FT:
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            length = math.dist(U0[a], U0[b])
            ring[a].append(length)
            ring[b].append(length)
    ratios = [math.dist(U0[i], U1[i]) / (sum(r) / len(r)) for i, r in enumerate(ring) if r]
    best = max(range(len(ratios)), key=lambda i: ratios[i])
    areas = [tri_area(U0[t[0]], U0[t[1]], U0[t[2]]) for t in FT]
    area_ratio = min(areas) / max(areas)
    # the pictures, by scaf itself
    for it in (0, 1):
        out, rep = fig.tmp("fig13_%d.obj" % it), fig.tmp("fig13_%d.json" % it)
        fig.scaf("param", mesh, "-o", out, "--init", "tutte", "--iterations", it, "--tolerance", 0, "--report",
                 rep, "--png", fig.path("fig13_iteration%d.png" % it), "--png-size", 300, "--checker", "--quiet")
        if it == 1:
            chk = fig.check_uv(out)
            d = read_json(rep)
            fig.claim("the map after one iteration is bijective (scaf check)", chk["bijective"])
            fig.claim("the program's first iteration is the API's: E %.6g vs %.6g" % (d["final_energy"], e1),
                      abs(d["final_energy"] - e1) <= 1e-9 * e1)
        fig.picture("fig13_iteration%d.png" % it, "%s: E %.4g" % ("Tutte's start" if it == 0 else
                                                                 "after one iteration", e0 if it == 0 else e1))
    fig.claim("one iteration lowers E by more than half: %.4g -> %.4g" % (e0, e1), e1 < 0.5 * e0)
    fig.claim("the largest displacement is %.1f 1-ring edge lengths (> 10)" % ratios[best], ratios[best] > 10)
    fig.rec["numbers"] = {"E_start": e0, "E_after_1": e1, "max_ratio": ratios[best], "vertex": best,
                          "vertices_over_10": sum(1 for r in ratios if r > 10), "area_ratio_start": area_ratio}
    fig.rec["headline"] = {"paper": "a vertex moves 150 1-ring edge lengths in one iteration",
                           "scaf": "%.0f 1-ring edge lengths; E %.3g -> %.3g in one iteration" % (ratios[best], e0, e1)}
    fig.rec["differs"] = (
        "The model is a hand (the paper's Fig. 13 model is not named); its Tutte start is more extreme "
        "(smallest / largest triangle area %.0e against the paper's 1e-6), so the step is longer than the "
        "paper's 150 edge lengths. The outcome, one iteration moving vertices far beyond their 1-ring, is "
        "the paper's." % area_ratio)
    fig.rec["scaf"] = (
        "On %s from Tutte's start (smallest / largest triangle area %.1e), one iteration takes E from %.4g "
        "to %.4g. The vertex that moves most (UV %d) travels **%.0f times** the mean edge length of its "
        "1-ring in the start; %d vertices move more than 10 such lengths. The map after the step is "
        "bijective (`scaf check`)." % (name, area_ratio, e0, e1, best, ratios[best],
                                       fig.rec["numbers"]["vertices_over_10"]))


if __name__ == "__main__":
    run(Figure("13", "Fig. 13: one iteration's large step", PAPER), body)
