#!/usr/bin/env python3
"""Fig. 8: components mapped to circles, then packed into an atlas.

One OBJ of several connected components and no UVs (disk/camel_b.obj and
disk/hand_lowres.obj, without their vt, and generated pieces: a bumpy
hemisphere, a plate with six holes, a grid, the spiral strip; the paper's
Maneki-Neko is not public) through `scaf atlas --seams input`: every
component is a chart, starts on a circle (Tutte), the circles on a grid;
the joint SCAF optimization lowers the distortion, then the packer and the
contracting scaffold pack them. The start is drawn by the same command
with --iterations 0 --compact-iterations 0 (--small: the generated pieces only). Claims: the atlas is bijective
with every gap at least the padding (scaf check), one chart per component."""
import os

from common import Figure, data_dir, read_json, report_rows, run

PAPER = ("A model with multiple components is parametrized automatically into a texture atlas: each "
         "component mapped to a circle (grid layout), then the distortion minimized and the charts packed "
         "tightly with no user interaction (Table 1: Maneki-Neko, 23,025 vertices, 43,648 faces, 50 "
         "iterations, 16.8 s).")
PAD = 4.0 / 1024


def read_vf(path):
    V, F = [], []
    with open(path) as f:
        for ln in f:
            p = ln.split()
            if not p:
                continue
            if p[0] == "v":
                V.append(tuple(float(x) for x in p[1:4]))
            elif p[0] == "f":
                idx = [int(t.split("/")[0]) for t in p[1:]]
                idx = [i - 1 if i > 0 else len(V) + i for i in idx]
                for k in range(1, len(idx) - 1):
                    F.append((idx[0], idx[k], idx[k + 1]))
    return V, F


def body(fig):
    parts = []
    for rel in () if fig.args.small else ("disk/camel_b.obj", "disk/hand_lowres.obj"):
        p = os.path.join(data_dir(), rel)
        if os.path.exists(p):
            parts.append(p)
        else:
            print("(%s absent: the atlas is made of the generated pieces only)" % rel)
    for name, size in (("hemisphere", 10), ("holes", 5), ("grid", 8), ("spiral", 26)):
        parts.append(fig.gen(name, size, fig.tmp("fig08_%s.obj" % name)))
    merged = fig.tmp("fig08_components.obj")
    nv, nf = 0, 0
    with open(merged, "w") as out:
        out.write("# bench/paper/fig08: %d components, no UVs\n" % len(parts))
        for k, p in enumerate(parts):
            V, F = read_vf(p)
            lo = [min(v[d] for v in V) for d in range(3)]
            hi = [max(v[d] for v in V) for d in range(3)]
            s = 1.0 / max(hi[d] - lo[d] for d in range(3))  # each piece about unit size, side by side
            for v in V:
                out.write("v %.17g %.17g %.17g\n" % ((v[0] - lo[0]) * s + 1.5 * k, (v[1] - lo[1]) * s,
                                                    (v[2] - lo[2]) * s))
            for t in F:
                out.write("f %d %d %d\n" % (t[0] + nv + 1, t[1] + nv + 1, t[2] + nv + 1))
            nv += len(V)
            nf += len(F)
    start = fig.tmp("fig08_start.obj")
    fig.scaf("atlas", merged, "--seams", "input", "--iterations", 0, "--compact-iterations", 0, "--no-rotate",
             "-o", start, "--png", fig.path("fig08_start.png"), "--png-size", 300, "--checker", "--quiet")
    out, rep = fig.tmp("fig08_atlas.obj"), fig.tmp("fig08_atlas.json")
    fig.scaf("atlas", merged, "--seams", "input", "-o", out, "--report", rep, "--png", fig.path("fig08_atlas.png"),
             "--png-size", 300, "--checker", "--quiet")
    d = read_json(rep)
    chk = fig.check_uv(out)
    fig.claim("one chart per component: %d charts for %d components" % (d["mesh"]["charts"], len(parts)),
              d["mesh"]["charts"] == len(parts))
    fig.claim("the atlas is bijective (scaf check)", chk["bijective"])
    fig.claim("every two charts at least the padding apart: %.6f >= %.6f" % (chk["min_chart_gap"], PAD),
              chk["min_chart_gap"] >= PAD)
    fig.picture("fig08_start.png", "the start: every component on a circle (Tutte), packed as circles")
    fig.picture("fig08_atlas.png", "the atlas: E %.4f, packing efficiency %.3f" %
                (d["final_energy"], chk["packing_efficiency"]))
    its = d["settle_iterations_run"] + d["compact_iterations_run"]
    fig.row("%d components (camel_b, hand_lowres, generated)" % len(parts), "Maneki-Neko (Fig. 8)", True,
            v=d["mesh"]["vertices"], f=d["mesh"]["faces"], it=its, seconds=d["seconds"],
            it_seconds=d["seconds"] / max(its, 1), **report_rows(d))
    fig.rec["numbers"] = {"components": len(parts), "faces": nf, "E": d["final_energy"],
                          "efficiency": chk["packing_efficiency"], "min_gap": chk["min_chart_gap"],
                          "settle": d["settle_iterations_run"], "compact": d["compact_iterations_run"],
                          "seconds": d["seconds"]}
    fig.rec["headline"] = {
        "paper": "Maneki-Neko components: circles, then a tight atlas (16.8 s)",
        "scaf": "%d components: bijective atlas, efficiency %.3f, gap >= padding, %.2f s" % (
            len(parts), chk["packing_efficiency"], d["seconds"])}
    fig.rec["scaf"] = (
        "`scaf atlas --seams input` on one OBJ of %d components without UVs (%d faces): %d settling + %d "
        "compacting iterations, %.2f s, E %.4f, packing efficiency %.3f, every gap at least 4 texels of 1024, "
        "bijective (`scaf check`)." % (len(parts), nf, d["settle_iterations_run"], d["compact_iterations_run"],
                                       d["seconds"], d["final_energy"], chk["packing_efficiency"]))


if __name__ == "__main__":
    run(Figure("8", "Fig. 8: components to circles, then packed", PAPER), body)
