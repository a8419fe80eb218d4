#!/usr/bin/env python3
"""Fig. 10: a bunny grown 30 times inside a box, never self-intersecting.

`scaf inflate closed/bunny.obj --scale 30` (the paper's bunny: 568
vertices, 1,132 faces) for 50 iterations (the paper's count; --small: 10),
with the final tets written out. Claims: the surface is free of
self-intersections (`scaf check --3d`, exact), every tet positive (`scaf
check` on the .mesh), the surface grew (its bounding-box diagonal)."""
from common import Figure, read_json, run

PAPER = ("The bunny is scaled up inside a box toward 30 times its size: no self-intersection appears "
         "despite the extreme, constrained deformation (shown after 0, 10, ..., 50 iterations; Table 1: "
         "Bunny, 568 vertices, 1,132 faces, scaffold 683/706 vertices and 6,209/6,289 tets, 50 iterations, "
         "7.16 s).")


def body(fig):
    mesh = fig.data("closed/bunny.obj")
    n = 10 if fig.args.small else 50
    out, rep, tets = fig.tmp("bunny_x30.obj"), fig.tmp("bunny_x30.json"), fig.tmp("bunny_x30.mesh")
    _, _, _, wall = fig.scaf("inflate", mesh, "-o", out, "--scale", 30, "--iterations", n, "--report", rep,
                             "--tets", tets, "--png", fig.path("fig10_bunny.png"), "--png-size", 220, "--quiet")
    d = read_json(rep)
    c3 = fig.check_3d(out)
    fig.claim("the inflated bunny is free of self-intersections (scaf check --3d: %d intersecting pairs)" %
              c3["intersecting_pairs"], c3["intersection_free"])
    code, o, _, _ = fig.scaf("check", "--json", tets, ok=(0, 1))
    import json
    ct = json.loads(o)
    fig.claim("every one of the %d tets is positive (scaf check on the .mesh)" % ct["tets"], ct["valid"])
    grow = d["bbox_diagonal_after"] / d["bbox_diagonal_before"]
    fig.claim("the surface grew: bounding-box diagonal x%.2f" % grow, grow > 1.5)
    its = d["per_iteration"]
    fig.picture("fig10_bunny.png", "the bunny (left) and after %d iterations toward x30 in its box (right)" % n)
    secs = sum(i["seconds"] for i in its)
    fig.row("closed/bunny.obj", "Bunny (Fig. 10)", False, v=568, f=1132, vs0=its[0]["scaffold_vertices"],
            vs1=its[-1]["scaffold_vertices"], fs0=its[0]["tets"], fs1=its[-1]["tets"], it=len(its), seconds=wall,
            it_seconds=secs / len(its))
    fig.rec["numbers"] = {"iterations": len(its), "diag_growth": grow, "energy": [i["energy"] for i in its],
                          "tets": [its[0]["tets"], its[-1]["tets"]], "seconds_wall": wall,
                          "quality_min_last": its[-1]["quality_min"]}
    fig.rec["headline"] = {"paper": "bunny toward x30 in a box, no self-intersection (50 it., 7.16 s)",
                           "scaf": "diagonal x%.2f, free (exact), all tets positive, %d it., %.1f s" % (
                               grow, len(its), wall)}
    fig.rec["scaf"] = (
        "`scaf inflate closed/bunny.obj --scale 30 --iterations %d` in its default box (3.76 times the "
        "bounding box): the bounding-box diagonal grows **x%.2f** (the box stops it short of x30, as in the "
        "paper, where the bunny fills its box); %d -> %d scaffold tets; %.1f s wall. The surface is free "
        "of self-intersections and every tet positive, both proved exactly." %
        (n, grow, its[0]["tets"], its[-1]["tets"], wall))


if __name__ == "__main__":
    run(Figure("10", "Fig. 10: bunny inflation", PAPER), body)
