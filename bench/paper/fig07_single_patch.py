#!/usr/bin/env python3
"""Fig. 7: one patch, bijective, where a locally injective map overlaps.

disk/bull_1.obj (a closed bull cut open to one disk with a long cut, 34,504
faces: the closest public stand-in for the paper's artist-cut animal,
39,040 faces) through scaf param, checked bijective. scaf has no locally
injective (SLIM without scaffold) mode, so the paper's left half is not
remade here; the locally injective but overlapping map shown instead is
the input UV of seams/myles_eight_seamed.obj (Fig. 5), which `scaf check`
rejects. Claims: scaf's map is bijective; the locally injective one is
not."""
from common import Figure, Skip, read_json, report_rows, run

PAPER = ("A mesh cut by an artist into a single chart: SLIM's locally injective map (left) overlaps itself "
         "in a highlighted region, so it cannot be a texture map; SCAF's (right) is bijective (Table 1: "
         "Animal, 19,937 vertices, 39,040 faces, 50 iterations, 15.4 s).")


def body(fig):
    mesh = fig.data("disk/bull_1.obj")
    out, rep = fig.tmp("bull.obj"), fig.tmp("bull.json")
    fig.scaf("param", mesh, "-o", out, "--report", rep, "--png", fig.path("fig07_bull.png"), "--png-size", 300,
             "--checker", "--quiet")
    d = read_json(rep)
    chk = fig.check_uv(out)
    fig.claim("bull_1: scaf's single-chart map is bijective (scaf check)", chk["bijective"])
    fig.picture("fig07_bull.png", "bull_1, one chart: E %.4f after %d iterations, bijective" %
                (d["final_energy"], d["iteration_count"]))
    fig.row("disk/bull_1.obj", "Animal (Fig. 7)", True, v=d["mesh"]["vertices"], f=d["mesh"]["faces"],
            it=d["iteration_count"], seconds=d["seconds"], it_seconds=d["median_seconds_per_iteration"],
            **report_rows(d))
    li = None
    try:
        eight = fig.data("seams/myles_eight_seamed.obj")
        li = fig.check_uv(eight)
        fig.claim("a locally injective map (eight's input UV: %d/%d triangles positive) is not bijective: %d "
                  "crossings, %d touchings" % (li["positive"], li["triangles"], li["boundary_crossings"],
                                              li["boundary_touchings"]),
                  li["positive"] == li["triangles"] and not li["bijective"])
    except Skip as e:
        print("skip the locally injective example: %s" % e)
    fig.rec["numbers"] = {"iterations": d["iteration_count"], "E": d["final_energy"], "seconds": d["seconds"],
                          "locally_injective_crossings": li and li["boundary_crossings"]}
    fig.rec["headline"] = {
        "paper": "animal, one chart: SLIM overlaps, SCAF bijective",
        "scaf": "bull_1 one chart: bijective, E %.4f in %d it.; a locally injective UV: %s crossings" % (
            d["final_energy"], d["iteration_count"], li["boundary_crossings"] if li else "?")}
    fig.rec["scaf"] = (
        "`scaf param` on disk/bull_1.obj (%d vertices, %d faces, one chart with a long cut): %d iterations, "
        "E %.4f, %.2f s, bijective (`scaf check`).%s" %
        (d["mesh"]["vertices"], d["mesh"]["faces"], d["iteration_count"], d["final_energy"], d["seconds"],
         "" if not li else " A locally injective map that overlaps, for contrast: the input UV of "
         "myles_eight_seamed.obj has all %d triangles positive and %d boundary crossings (`scaf check`: "
         "not bijective)." % (li["triangles"], li["boundary_crossings"])))
    fig.rec["differs"] = ("Not remade: SLIM's locally injective result (the left half). scaf has no mode "
                          "without the scaffold, so it cannot produce the overlapping map; the contrast uses "
                          "a locally injective UV from the data set instead.")


if __name__ == "__main__":
    run(Figure("7", "Fig. 7: single patch, bijective vs locally injective", PAPER), body)
